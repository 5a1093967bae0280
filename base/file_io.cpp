#include "base/file_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

#include "base/input_error.h"

namespace acdplan {

namespace {

[[noreturn]] void CannotRead(const std::string& path, const std::string& why) {
  throw InputError(path + ": cannot read the file: " + why);
}

}  // namespace

std::ifstream OpenFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) CannotRead(path, "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) CannotRead(path, std::strerror(errno));
  return in;
}

void CheckRead(const std::istream& in, const std::string& path) {
  if (in.bad()) CannotRead(path, "read error");
}

std::string ReadFile(const std::string& path) {
  std::ifstream in = OpenFile(path);
  std::string text = ReadRest(in);
  CheckRead(in, path);
  return text;
}

std::string ReadRest(std::istream& in) {
  std::string text;
  using Position = std::istream::pos_type;
  // Where the stream can tell how much is left, room for all of it first.
  if (const Position here = in.tellg(); here != Position(-1)) {
    if (in.seekg(0, std::ios::end)) {
      const Position end = in.tellg();
      if (end != Position(-1) && end > here) text.reserve(static_cast<size_t>(end - here));
    }
    in.clear(in.rdstate() & std::ios::badbit);
    in.seekg(here);
  }
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) text.append(block, in.gcount());
  return text;
}

std::string UnreadableFileReason(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec) return ec.message();
  return std::filesystem::is_regular_file(status) ? "" : "not a regular file";
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  auto fail = [&path](const std::string& why) {
    throw std::runtime_error(path + ": cannot write the file: " + why);
  };
  namespace fs = std::filesystem;
  if (path.empty()) throw std::runtime_error("cannot write a file with an empty name");
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) fail("cannot create the folder '" + parent.string() + "': " + ec.message());
  }

  // O_EXCL with a random suffix instead of mkstemp(), whose files get mode 0600.
  std::random_device entropy;
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, ".tmp-%06x", static_cast<unsigned>(entropy() & 0xffffff));
    temporary = path + suffix;
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(std::strerror(errno));
  }
  if (fd < 0) fail("cannot create a temporary file");

  auto discard = [&](int error) {
    ::unlink(temporary.c_str());
    fail(std::strerror(error));
  };
  const char* data = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      discard(error);
    }
    data += written;
    left -= static_cast<size_t>(written);
  }
  if (::close(fd) != 0) discard(errno);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) discard(errno);
}

void CheckOutputPath(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(option + " " + path + ": is a directory");
  }
}

}  // namespace acdplan
