// Hostile files through a program, as a user meets them (hostile_process_test.cpp,
// hostile_picture_process_test.cpp): each must end the process with exit code 1 and one line
// on stderr naming the file, not a signal (a stack overflow is SIGSEGV), not a hang, and without
// memory out of proportion to the file: its peak stays within a margin of the same program
// refusing a file that claims nothing.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "pipeserver/hostile_files.hpp"

extern char** environ;

namespace l2::hostile_run {

namespace fs = std::filesystem;

// What a program did: its exit code (-signal when a signal ended it, -1000 when it overstayed
// and was killed), its stderr and stdout, its peak memory.
struct Ended {
  int code = 0;
  std::string output;
  long peak_kib = 0;
};

// `args[0]` run, its stdout and stderr together in `output`.
inline Ended run(std::vector<std::string> args, const fs::path& output) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 2, 1);
  Ended e;
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Far above what any refusal takes, on a loaded machine or under ASan: only a hang overstays
  // it.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      e.code = -1000;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (e.code == 0) e.code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  e.peak_kib = usage.ru_maxrss;
  std::ifstream in(output);
  e.output.assign(std::istreambuf_iterator<char>(in), {});
  return e;
}

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
    return run(args, dir_ / "output.txt");
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
