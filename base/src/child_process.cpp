#include "base/child_process.hpp"

#include "base/process_table.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <thread>

extern char** environ;

namespace l2 {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

ExitStatus decode_wait_status(int status) {
  ExitStatus s;
  if (WIFEXITED(status)) s.code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) s.signal = WTERMSIG(status);
  return s;
}

// This process's environment without the variables `extra` sets, then `extra`. The strings
// stay owned by environ and `extra`, which outlive the spawn.
std::vector<char*> environment_with(std::vector<std::string>& extra) {
  std::vector<char*> env;
  for (char** e = environ; *e; ++e) {
    const std::string_view entry(*e);
    const auto set_by_extra = [&](const std::string& x) {
      const auto name = x.substr(0, x.find('=') + 1);
      return entry.substr(0, name.size()) == name;
    };
    if (std::none_of(extra.begin(), extra.end(), set_by_extra)) env.push_back(*e);
  }
  for (std::string& x : extra) env.push_back(x.data());
  env.push_back(nullptr);
  return env;
}

// A pipe whose write end the child gets as its stdout or stderr.
struct CapturePipe {
  Fd read, write;
};

CapturePipe make_pipe(const std::string& program) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    throw std::runtime_error(
        fmt::format("cannot start {}: pipe: {}", program, std::strerror(errno)));
  }
  return {Fd(fds[0]), Fd(fds[1])};
}

void reap(pid_t pid, std::optional<ExitStatus>& status) {
  int raw = 0;
  while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
  }
  status = decode_wait_status(raw);
}

}  // namespace

std::string ExitStatus::describe() const {
  if (gone && !gone_how.empty()) return gone_how;
  if (gone) return "is gone (its connection to the coordinator closed: killed or crashed)";
  if (signal != 0) return fmt::format("killed by signal {} ({})", signal, strsignal(signal));
  return fmt::format("exited with code {}", code);
}

ChildProcess::ChildProcess(std::vector<std::string> argv, std::vector<std::string> env,
                           Capture capture)
    : argv_(std::move(argv)) {
  if (argv_.empty()) throw std::invalid_argument("ChildProcess: no program given");
  std::vector<char*> args;
  for (auto& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  std::vector<char*> envp = environment_with(env);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const bool wanted[2] = {capture.out, capture.err};
  CapturePipe pipes[2];
  for (int i = 0; i < 2; ++i) {
    if (!wanted[i]) continue;
    pipes[i] = make_pipe(argv_[0]);
    posix_spawn_file_actions_adddup2(&actions, pipes[i].write.get(), STDOUT_FILENO + i);
  }
  const int rc = posix_spawnp(&pid_, args[0], &actions, nullptr, args.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    pid_ = -1;
    throw std::runtime_error(fmt::format("cannot start {}: {}", argv_[0], std::strerror(rc)));
  }
  // The write ends close here: the child holds its copies, so a stream ends when it does.
  for (int i = 0; i < 2; ++i) pipes_[i] = std::move(pipes[i].read);
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : argv_(std::move(other.argv_)),
      pid_(std::exchange(other.pid_, -1)),
      status_(other.status_),
      pipes_{std::move(other.pipes_[0]), std::move(other.pipes_[1])},
      buffers_{std::move(other.buffers_[0]), std::move(other.buffers_[1])} {}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !status_) terminate();
}

bool ChildProcess::stopped() const {
  if (pid_ <= 0 || status_) return false;
  const char state = process_state(pid_);
  return state == 'T' || state == 't';
}

std::optional<ExitStatus> ChildProcess::poll() {
  if (status_ || pid_ <= 0) return status_;
  int status = 0;
  pid_t r;
  do {
    r = waitpid(pid_, &status, WNOHANG);
  } while (r < 0 && errno == EINTR);
  if (r == pid_) status_ = decode_wait_status(status);
  return status_;
}

std::optional<ExitStatus> ChildProcess::wait_for(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (!poll()) {
    if (Clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(milliseconds(5));
  }
  return status_;
}

void ChildProcess::signal(int sig) {
  // pid_ <= 0 (moved from): kill(-1) would signal every process we may signal.
  if (pid_ > 0 && !poll()) ::kill(pid_, sig);
}

void ChildProcess::request_stop() {
  signal(SIGTERM);
}

ExitStatus ChildProcess::terminate(milliseconds grace) {
  if (poll()) return *status_;
  if (pid_ <= 0) return ExitStatus{};  // moved from: nothing of ours to end
  ::kill(pid_, SIGTERM);
  if (wait_for(grace)) return *status_;
  ::kill(pid_, SIGKILL);
  reap(pid_, status_);
  return *status_;
}

bool ChildProcess::pump(milliseconds timeout) {
  pollfd p[2] = {{pipes_[0].get(), POLLIN, 0}, {pipes_[1].get(), POLLIN, 0}};
  if (!pipes_[0] && !pipes_[1]) return false;
  if (::poll(p, 2, static_cast<int>(timeout.count())) <= 0) return true;
  for (int i = 0; i < 2; ++i) {
    if (!pipes_[i] || p[i].revents == 0) continue;
    char buffer[4096];
    const ssize_t n = ::read(pipes_[i].get(), buffer, sizeof buffer);
    if (n > 0) {
      buffers_[i].append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      pipes_[i].reset();
    }
  }
  return true;
}

std::optional<std::string> ChildProcess::read_line(Stream stream, milliseconds timeout) {
  std::string& buffer = buffers_[static_cast<int>(stream)];
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    if (const std::size_t nl = buffer.find('\n'); nl != std::string::npos) {
      std::string line = buffer.substr(0, nl);
      buffer.erase(0, nl + 1);
      return line;
    }
    if (!pipes_[static_cast<int>(stream)]) return std::nullopt;
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return std::nullopt;
    pump(std::min(left, milliseconds(50)));
  }
}

Finished ChildProcess::finish(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  Finished result;
  if (pid_ <= 0) return result;  // moved from: nothing of ours to wait for
  while (pump(milliseconds(20)) && Clock::now() < deadline) {
  }
  if (pipes_[0] || pipes_[1] ||
      !wait_for(std::chrono::duration_cast<milliseconds>(
          std::max(deadline - Clock::now(), Clock::duration::zero())))) {
    // Overstayed: a process of its own that inherited the pipes may keep them open, so what
    // is still unread is left.
    result.killed = !poll();
    if (result.killed) ::kill(pid_, SIGKILL);
    if (!status_) reap(pid_, status_);
    pump(milliseconds(0));
  }
  result.status = *status_;
  result.out = std::move(buffers_[0]);
  result.err = std::move(buffers_[1]);
  return result;
}

Finished run(std::vector<std::string> argv, milliseconds timeout) {
  ChildProcess child(std::move(argv), {}, Capture{true, true});
  return child.finish(timeout);
}

Finished run_shell(const std::string& command, milliseconds timeout) {
  ChildProcess child({"/bin/sh", "-c", "exec 2>&1; " + command}, {}, Capture{true, false});
  return child.finish(timeout);
}

}  // namespace l2
