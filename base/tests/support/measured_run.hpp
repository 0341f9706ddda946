// A program run to its end for a test that checks how it ends and what it costs: its exit code,
// its stdout and stderr together, and its peak memory (wait4's ru_maxrss), with a deadline so
// that a hang fails the test instead of holding up the suite. l2::ChildProcess does not measure
// memory. Tests of several folders use it (lightning2_emu's, pipeserver's), so it lives at the
// bottom of the layers, in base, as the library l2_measured_run (base/CMakeLists.txt).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace l2::process_run {

// What a program did: its exit code (-signal when a signal ended it, -1000 when it overstayed
// and was killed, -1001 when it could not be started), its stdout and stderr, its peak memory.
struct Ended {
  int code = 0;
  std::string output;
  long peak_kib = 0;
};

// Far above what any program a test runs this way takes, on a loaded machine or under ASan:
// only a hang overstays it.
inline constexpr std::chrono::seconds kBound{120};

// `args[0]` (a path) run with `args`, its stdout and stderr together written to `output` and
// read back.
inline Ended run(std::vector<std::string> args, const std::filesystem::path& output) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 2, 1);
  Ended e;
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) {
    return {-1001, "cannot start " + args[0] + ": " + std::strerror(failed), 0};
  }
  const auto deadline = std::chrono::steady_clock::now() + kBound;
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

}  // namespace l2::process_run
