// Shared by the `l2wall golden` command-line tests: running l2wall and idiff, and a fixture
// holding a temporary copy of the repository's golden folder.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "base/child_process.hpp"

namespace l2::test {

namespace fs = std::filesystem;

struct Result {
  int code = -1;
  std::string output;  // stdout and stderr
};

inline Result run(const std::string& command) {
  const Finished f = run_shell(command, std::chrono::minutes(5));
  Result r;
  r.output = f.out;
  r.code = f.status.shell_code();
  return r;
}

inline std::string quote(const fs::path& p) {
  return "'" + p.string() + "'";
}

inline Result l2wall(const std::string& args) {
  return run(std::string(L2WALL_PATH) + " golden " + args);
}

// idiff's own verdict on a pair: 0 the same, non-zero different.
inline int idiff(const fs::path& a, const fs::path& b) {
  return run("idiff -q " + quote(a) + " " + quote(b)).code;
}

inline const fs::path kSource = L2_SOURCE_DIR;
inline const std::string kPattern = "kd-2x2-test-pattern";

class GoldenCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("l2-golden-cli-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::copy(kSource / "tests/golden_images", goldens(), fs::copy_options::recursive);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  fs::path goldens() const { return dir_ / "goldens"; }
  fs::path out() const { return dir_ / "out"; }
  fs::path golden(const std::string& entry, int display) const {
    return goldens() / entry / ("display-" + std::to_string(display) + ".png");
  }
  std::string common() const { return "--goldens " + quote(goldens()) + " --out " + quote(out()); }

  fs::path dir_;
};

}  // namespace l2::test
