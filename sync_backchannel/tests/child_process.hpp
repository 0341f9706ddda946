// A child process with its stdout and stderr captured, for tests that run real programs
// (socat, the sync_backchannel executable). Every wait is bounded.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace l2::test {

struct ChildResult {
  int exit_code = -1;  // -1 when killed by a signal
  int signal = 0;
  std::string out;
  std::string err;
};

class ChildProcess {
 public:
  explicit ChildProcess(const std::vector<std::string>& argv);
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess();  // kills and reaps a child still running

  // One line (without '\n') from stdout or stderr; "" if none arrived within `timeout`.
  std::string read_out_line(std::chrono::milliseconds timeout) { return read_line(0, timeout); }
  std::string read_err_line(std::chrono::milliseconds timeout) { return read_line(1, timeout); }
  void send_signal(int sig);
  // Collects the rest of both streams until the child closes them, then reaps it. After
  // `timeout` the child is killed (and the result says so).
  ChildResult wait(std::chrono::milliseconds timeout);
  pid_t pid() const { return pid_; }

 private:
  std::string read_line(int stream, std::chrono::milliseconds timeout);
  bool pump(std::chrono::milliseconds timeout);  // reads what is there; false when both closed

  pid_t pid_ = -1;
  int fds_[2] = {-1, -1};
  std::string buffers_[2];
};

// Runs to completion (bounded by `timeout`).
ChildResult run(const std::vector<std::string>& argv, std::chrono::milliseconds timeout);

}  // namespace l2::test
