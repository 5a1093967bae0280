#include "fuzz/fuzz_input.h"

#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "base/file_io.h"

namespace acdplan::fuzz {
namespace {

std::string* folder = nullptr;  // Made once per process; never freed (used until exit).

void RemoveFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(*folder, ignored);
}

const std::string& Folder() {
  if (folder == nullptr) {
    const char* tmpdir = std::getenv("TMPDIR");
    std::string pattern = std::string(tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp") +
                          "/acdplan-fuzz-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (mkdtemp(buffer.data()) == nullptr) {
      std::perror("acdplan fuzz: mkdtemp");
      std::abort();
    }
    folder = new std::string(buffer.data());
    std::atexit(RemoveFolder);
  }
  return *folder;
}

}  // namespace

std::string InputText(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

std::string WriteInputFile(const std::string& name, const std::string& text) {
  const std::string path = Folder() + "/" + name;
  WriteFileAtomically(path, text);
  return path;
}

}  // namespace acdplan::fuzz
