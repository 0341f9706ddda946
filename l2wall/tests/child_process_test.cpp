#include "child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>

namespace l2 {
namespace {

using namespace std::chrono_literals;

bool process_exists(pid_t pid) {
  return kill(pid, 0) == 0;
}

TEST(ChildProcess, ReportsExitCode) {
  ChildProcess p({"/bin/sh", "-c", "exit 3"});
  const auto status = p.wait_for(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(status->code, 3);
  EXPECT_FALSE(status->ok());
  EXPECT_EQ(status->describe(), "exited with code 3");
}

TEST(ChildProcess, PollDoesNotBlockWhileRunning) {
  ChildProcess p({"/bin/sleep", "5"});
  EXPECT_FALSE(p.poll());
  EXPECT_TRUE(process_exists(p.pid()));
}

TEST(ChildProcess, TerminateEndsAndReapsAStubbornChild) {
  // The child ignores SIGTERM, so only the SIGKILL after the grace period ends it.
  ChildProcess p({"/bin/sh", "-c", "trap '' TERM; while :; do sleep 0.05; done"});
  std::this_thread::sleep_for(100ms);
  const pid_t pid = p.pid();
  const ExitStatus s = p.terminate(200ms);
  EXPECT_EQ(s.signal, SIGKILL);
  EXPECT_EQ(s.describe(), "killed by signal 9 (Killed)");
  EXPECT_FALSE(process_exists(pid));  // reaped: not even a zombie
}

TEST(ChildProcess, RequestStopAsksWithoutWaiting) {
  ChildProcess p({"/bin/sleep", "30"});
  const auto t0 = std::chrono::steady_clock::now();
  p.request_stop();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 100ms);
  const auto status = p.wait_for(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(status->signal, SIGTERM);
  p.request_stop();  // after it ended: no signal to a pid that may be reused
}

TEST(ChildProcess, DestructorLeavesNoOrphan) {
  pid_t pid = 0;
  {
    ChildProcess p({"/bin/sleep", "30"});
    pid = p.pid();
    ASSERT_TRUE(process_exists(pid));
  }
  EXPECT_FALSE(process_exists(pid));
}

TEST(ChildProcess, MissingProgramIsAClearError) {
  try {
    ChildProcess p({"/nonexistent/pipeserver"});
    // posix_spawn may report ENOENT through the child's exit code 127 instead.
    const auto s = p.wait_for(5s);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->code, 127);
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot start /nonexistent/pipeserver: No such file or directory");
  }
}

}  // namespace
}  // namespace l2
