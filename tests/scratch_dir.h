#pragma once
// Scratch folders for tests that write files, under the system temp dir and named by the process (ctest runs the
// float and double instances of a test at the same time); removed with the object, so a passing run leaves nothing.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace gqtest {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The test process's own folder, made on first use and removed at exit.
inline const std::filesystem::path& processScratchDir() {
  static const ScratchDir dir("gq_tests");
  return dir.path();
}

}  // namespace gqtest
