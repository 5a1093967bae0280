#include "base/file_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <utility>

#include "base/input_error.h"
#include "tests/scratch_dir.h"

namespace acdplan {
namespace {

namespace fs = std::filesystem;

class FileIoTest : public ::testing::Test {
 protected:
  static std::string Read(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  int FileCount() const {
    int n = 0;
    for (auto it = fs::recursive_directory_iterator(dir_); it != fs::recursive_directory_iterator();
         ++it) {
      n += it->is_regular_file() ? 1 : 0;
    }
    return n;
  }
  /// The message of the exception `write` throws, "" if none.
  template <typename Exception, typename Write>
  static std::string MessageOf(Write write) {
    try {
      write();
    } catch (const Exception& error) {
      return error.what();
    }
    return "";
  }
  test::ScratchDir scratch_{"acdplan_file_io_test"};
  fs::path dir_ = scratch_.path();
};

TEST_F(FileIoTest, WriteCreatesFoldersAndLeavesNoTemporaryFile) {
  const fs::path path = dir_ / "a" / "b" / "out.json";
  WriteFileAtomically(path.string(), "first");
  EXPECT_EQ(Read(path), "first");
  WriteFileAtomically(path.string(), "second, longer");  // replaces
  EXPECT_EQ(Read(path), "second, longer");
  EXPECT_EQ(FileCount(), 1);
}

TEST_F(FileIoTest, WriteFailsClearlyOnAnUnwritablePath) {
  fs::create_directories(dir_);
  // A folder where the file should be: rename() cannot replace it.
  const fs::path taken = dir_ / "taken";
  fs::create_directories(taken);
  const std::string message =
      MessageOf<std::runtime_error>([&] { WriteFileAtomically(taken.string(), "x"); });
  EXPECT_EQ(message.rfind(taken.string() + ": cannot write the file: ", 0), 0u) << message;
  EXPECT_EQ(FileCount(), 0);

  // A parent that is a regular file.
  std::ofstream(dir_ / "file") << "x";
  const fs::path below_file = dir_ / "file" / "out.svg";
  const std::string below =
      MessageOf<std::runtime_error>([&] { WriteFileAtomically(below_file.string(), "x"); });
  EXPECT_EQ(
      below.rfind(below_file.string() + ": cannot write the file: cannot create the folder", 0), 0u)
      << below;
  EXPECT_EQ(FileCount(), 1);
}

TEST_F(FileIoTest, WriteFailsClearlyInAReadOnlyFolder) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
  fs::create_directories(dir_);
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  const fs::path path = dir_ / "out.json";
  const std::string message =
      MessageOf<std::runtime_error>([&] { WriteFileAtomically(path.string(), "x"); });
  EXPECT_EQ(message, path.string() + ": cannot write the file: Permission denied");
  fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
  EXPECT_EQ(FileCount(), 0);
}

TEST_F(FileIoTest, ReadGivesTheBytesBack) {
  const fs::path path = dir_ / "in.txt";
  const std::string text("line 1\r\nline 2\0 after a NUL\n", 28);
  WriteFileAtomically(path.string(), text);
  EXPECT_EQ(ReadFile(path.string()), text);
}

// A stream that cannot seek or tell its position (a pipe), in pieces of 5 bytes.
class PipeBuffer : public std::streambuf {
 public:
  explicit PipeBuffer(std::string text) : text_(std::move(text)) {}

 protected:
  int_type underflow() override {
    if (at_ >= text_.size()) return traits_type::eof();
    const size_t size = std::min<size_t>(5, text_.size() - at_);
    char* begin = text_.data() + at_;
    at_ += size;
    setg(begin, begin, begin + size);
    return traits_type::to_int_type(*begin);
  }

 private:
  std::string text_;
  size_t at_ = 0;
};

TEST_F(FileIoTest, ReadRestReadsWhatIsLeftOfAnyStream) {
  const fs::path path = dir_ / "in.bin";
  std::string text(200000, '\0');
  for (size_t k = 0; k < text.size(); ++k) text[k] = static_cast<char>(k * 7919 % 256);
  WriteFileAtomically(path.string(), text);
  std::ifstream file = OpenFile(path.string());
  EXPECT_EQ(ReadRest(file), text);
  EXPECT_EQ(ReadRest(file), "");  // At the end.
  std::ifstream partly = OpenFile(path.string());
  partly.ignore(1000);  // From where a reader has got to.
  EXPECT_EQ(ReadRest(partly), text.substr(1000));
  std::istringstream string_stream(text);
  EXPECT_EQ(ReadRest(string_stream), text);
  PipeBuffer pipe_buffer(text.substr(0, 70003));
  std::istream pipe(&pipe_buffer);
  EXPECT_EQ(ReadRest(pipe), text.substr(0, 70003));
  EXPECT_EQ(MessageOf<InputError>([&] { OpenFile(dir_.string()); }),
            dir_.string() + ": cannot read the file: it is a directory");
}

TEST_F(FileIoTest, ReadNamesTheFileAndTheReason) {
  const std::string missing = (dir_ / "none.yaml").string();
  EXPECT_EQ(MessageOf<InputError>([&] { ReadFile(missing); }),
            missing + ": cannot read the file: No such file or directory");
  fs::create_directories(dir_);
  EXPECT_EQ(MessageOf<InputError>([&] { ReadFile(dir_.string()); }),
            dir_.string() + ": cannot read the file: it is a directory");
}

TEST_F(FileIoTest, UnreadableFileReasonSaysWhyWithoutThrowing) {
  const fs::path path = dir_ / "in.txt";
  WriteFileAtomically(path.string(), "x");
  EXPECT_EQ(UnreadableFileReason(path.string()), "");
  EXPECT_EQ(UnreadableFileReason(dir_.string()), "not a regular file");
  EXPECT_EQ(UnreadableFileReason((dir_ / "none").string()), "No such file or directory");
  EXPECT_EQ(UnreadableFileReason((dir_ / std::string(300, 'x')).string()), "File name too long");
}

}  // namespace
}  // namespace acdplan
