#include "child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <thread>

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
  // A child that ignores SIGTERM: a request_stop that waited for the end (as terminate does)
  // would return only after a grace period, or leave it ended.
  ChildProcess p({"/bin/sh", "-c", "trap '' TERM; while :; do sleep 0.05; done"});
  std::this_thread::sleep_for(100ms);  // the trap is set
  p.request_stop();
  EXPECT_FALSE(p.poll()) << "request_stop waited for, or forced, the end";
  EXPECT_TRUE(process_exists(p.pid()));
  EXPECT_EQ(p.terminate(200ms).signal, SIGKILL);
  p.request_stop();  // after it ended and was reaped: its pid may be reused, nothing is sent
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
