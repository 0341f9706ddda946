// Hostile files through a program, as a user meets them (hostile_process_test.cpp,
// hostile_picture_process_test.cpp): each must end the process with exit code 1 and one line
// on stderr naming the file, not a signal (a stack overflow is SIGSEGV), not a hang, and without
// memory out of proportion to the file: its peak stays within a margin of the same program
// refusing a file that claims nothing. Each run is measured by base/tests/measured_run.hpp.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "measured_run.hpp"
#include "pipeserver/hostile_files.hpp"

namespace l2::hostile_run {

namespace fs = std::filesystem;

using process_run::Ended;

class HostileProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("l2_hostile_process_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes) const {
    hostile::write(dir_ / name, bytes);
    return dir_ / name;
  }
  // A program's command line around a file: `before` it (the option naming it last, if any) and
  // `after` it.
  struct Command {
    std::string program;
    std::vector<std::string> before, after;
  };
  Ended run_on(const Command& c, const fs::path& f) const {
    std::vector<std::string> args = {c.program};
    args.insert(args.end(), c.before.begin(), c.before.end());
    args.push_back(f.string());
    args.insert(args.end(), c.after.begin(), c.after.end());
    return process_run::run(args, dir_ / "output.txt");
  }
  // Each file through `c`: exit 1, one line naming the file after the program's name, the peak
  // within a margin of the baseline file's.
  void expect_refused(const Command& c, const fs::path& baseline_file,
                      const std::vector<std::pair<std::string, std::string>>& files) const {
    const Ended baseline = run_on(c, baseline_file);
    ASSERT_EQ(baseline.code, 1) << baseline.output;
    const std::string name = fs::path(c.program).filename().string();
    for (const auto& [file_name, bytes] : files) {
      const fs::path f = file(file_name, bytes);
      const Ended e = run_on(c, f);
      EXPECT_EQ(e.code, 1) << file_name << ": " << e.output;
      EXPECT_EQ(e.output.rfind(name + ": " + f.string() + ": ", 0), 0u) << e.output;
      EXPECT_EQ(e.output.find('\n'), e.output.size() - 1) << e.output;
      // A margin for what reading a file of a few bytes to a few MB takes; what the files claim
      // is gigabytes.
      EXPECT_LT(e.peak_kib, baseline.peak_kib + 100 * 1024) << file_name;
    }
  }
  fs::path dir_;
};

}  // namespace l2::hostile_run
