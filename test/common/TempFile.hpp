#pragma once
// Temporary files for tests: a per-test, per-process path in the system temp folder, and a guard
// that removes the file when the test ends.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace peridot {
namespace testing {

inline std::string tempPath(const std::string& stem) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = std::string("peridot_") + info->test_suite_name() + "_" + info->name() +
                           "_" + std::to_string(::getpid()) + "_" + stem;
  return (std::filesystem::temp_directory_path() / name).string();
}

// Removes a file at the end of a test.
struct TempFile {
  explicit TempFile(std::string p) : path(std::move(p)) {}
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
  std::string path;
};

}  // namespace testing
}  // namespace peridot
