#include "base/process_table.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

#include "base/child_process.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;

// Waits up to 5 s for process `pid` to reach `state`, and says what it reached.
char wait_for_state(pid_t pid, char state) {
  const auto give_up = std::chrono::steady_clock::now() + 5s;
  while (process_state(pid) != state && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(5ms);
  return process_state(pid);
}

TEST(ProcessTable, FollowsAProcessThroughStoppedZombieAndGone) {
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    for (;;) pause();
  }
  EXPECT_EQ(wait_for_state(pid, 'S'), 'S');
  EXPECT_TRUE(process_running(pid));
  ASSERT_EQ(kill(pid, SIGSTOP), 0);
  EXPECT_EQ(wait_for_state(pid, 'T'), 'T');
  EXPECT_TRUE(process_running(pid)) << "a stopped process still runs: it may be continued";
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  EXPECT_EQ(wait_for_state(pid, 'Z'), 'Z') << "killed but not reaped";
  EXPECT_FALSE(process_running(pid));
  ASSERT_EQ(waitpid(pid, nullptr, 0), pid);
  EXPECT_EQ(process_state(pid), '\0');
  EXPECT_FALSE(process_running(pid));
  EXPECT_EQ(process_command_line(pid), "");
}

// Whether `pids` holds `pid`.
bool holds(const std::vector<pid_t>& pids, pid_t pid) {
  return std::find(pids.begin(), pids.end(), pid) != pids.end();
}

TEST(ProcessTable, FindsProcessesByAWholeArgumentOfTheirCommandLine) {
  const std::string mark = "process-table-test-" + std::to_string(getpid());
  // A loop, so the shell stays itself (a lone command it would exec in its place). Each
  // `sleep` it starts is a fork of it, holding its command line until it execs: found too.
  ChildProcess child({"/bin/sh", "-c", "while :; do sleep 1; done", mark});
  const std::string whole = std::string(1, '\0') + mark + '\0';
  std::vector<pid_t> found;
  const auto give_up = std::chrono::steady_clock::now() + 5s;
  while (!holds(found, child.pid()) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(5ms);
    found = processes_with_command_line(whole);
  }
  EXPECT_TRUE(holds(found, child.pid()));
  EXPECT_LE(found.size(), 2u) << "more than the shell and a fork of it";
  EXPECT_EQ(process_command_line(child.pid()),
            std::string("/bin/sh\0-c\0while :; do sleep 1; done\0", 37) + mark + '\0');
  EXPECT_TRUE(processes_with_command_line(whole.substr(0, whole.size() - 2) + '\0').empty())
      << "an argument's start alone matched as the whole argument";
  child.terminate();
  const auto gone_by = std::chrono::steady_clock::now() + 5s;
  while (!processes_with_command_line(whole).empty() && std::chrono::steady_clock::now() < gone_by)
    std::this_thread::sleep_for(5ms);
  EXPECT_TRUE(processes_with_command_line(whole).empty());
}

TEST(ProcessTable, NoProcessHasNoState) {
  EXPECT_EQ(process_state(0), '\0');
  EXPECT_EQ(process_state(-1), '\0');
  EXPECT_EQ(process_command_line(0), "");
}

}  // namespace
}  // namespace l2
