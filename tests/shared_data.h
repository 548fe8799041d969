#pragma once
// The shared data folder (real robots and meshes, kept outside the repository): $GQ_SHARED_DIR when it is set, else
// the folder configured at build time (the CMake cache variable GQ_SHARED_DIR, by default ../shared beside the
// checkout). Tests that read it sit in test suites whose name ends in "Data" (ctest label `data`, every other test is
// `fast`: tests/CMakeLists.txt); when a file they need is missing they are skipped, naming the path they looked for,
// so a checkout without the data still runs every other test and fails none.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace gqtest {

inline std::string sharedDir() {
  if (const char* env = std::getenv("GQ_SHARED_DIR"); env != nullptr && *env != '\0') return env;
#ifdef GQ_SHARED_DIR
  return GQ_SHARED_DIR;
#else
  return "../shared";
#endif
}

// A path inside the shared data folder, e.g. sharedPath("meshes/stanford-bunny.obj").
inline std::string sharedPath(const std::string& relative) { return sharedDir() + "/" + relative; }

inline bool sharedFileExists(const std::string& path) {
  std::error_code ignored;
  return std::filesystem::exists(path, ignored);
}

}  // namespace gqtest

// Skips the running test unless `path` exists, with a message naming the path. Use it in a test body or in a
// fixture's SetUp (GTEST_SKIP returns from the enclosing function; from SetUp it also skips the body).
#define GQ_REQUIRE_SHARED_FILE(path)                                                                           \
  do {                                                                                                         \
    const std::string gq_required_path_ = (path);                                                              \
    if (!::gqtest::sharedFileExists(gq_required_path_))                                                        \
      GTEST_SKIP() << "shared data not found: " << gq_required_path_ << " (set GQ_SHARED_DIR to the data folder)"; \
  } while (false)
