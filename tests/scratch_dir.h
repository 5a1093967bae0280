#pragma once
// A test's scratch folder: fresh, unique to the test and the process, removed afterwards.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace acdplan::test {

/// A fresh folder under the system's temporary folder, named after the running test and the
/// process (ctest runs every test in its own process, in parallel), removed with everything in
/// it when the object goes away. Construct it inside a test or a fixture.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix = "acdplan") {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = prefix + "_" + std::to_string(::getpid());
    if (info != nullptr) name += std::string("_") + info->test_suite_name() + "_" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';  // Parameterised tests' names hold slashes.
    }
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;  // A test may have made a file read-only; removal must not throw.
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// The path of `name` inside the folder (not created).
  std::string Path(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `text` to `name` in the folder and returns the file's path.
  std::string Write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file.string();
  }

 private:
  std::filesystem::path path_;
};

}  // namespace acdplan::test
