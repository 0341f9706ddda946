// A scratch folder of the running test's own (`prefix`, the run's random seed and the test's
// name), so that tests run side by side never share a file.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace l2 {

inline std::filesystem::path test_folder(const std::string& prefix) {
  const auto* test = ::testing::UnitTest::GetInstance();
  auto dir = std::filesystem::temp_directory_path() /
             (prefix + std::to_string(test->random_seed()) + test->current_test_info()->name());
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace l2
