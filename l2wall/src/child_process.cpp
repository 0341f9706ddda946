#include "child_process.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>

extern char** environ;

namespace l2 {
namespace {

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

}  // namespace

std::string ExitStatus::describe() const {
  if (signal != 0) return fmt::format("killed by signal {} ({})", signal, strsignal(signal));
  return fmt::format("exited with code {}", code);
}

ChildProcess::ChildProcess(std::vector<std::string> argv, std::vector<std::string> env)
    : argv_(std::move(argv)) {
  if (argv_.empty()) throw std::invalid_argument("ChildProcess: no program given");
  std::vector<char*> args;
  for (auto& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  std::vector<char*> envp = environment_with(env);
  const int rc = posix_spawn(&pid_, args[0], nullptr, nullptr, args.data(), envp.data());
  if (rc != 0) {
    pid_ = -1;
    throw std::runtime_error(fmt::format("cannot start {}: {}", argv_[0], std::strerror(rc)));
  }
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : argv_(std::move(other.argv_)), pid_(other.pid_), status_(other.status_) {
  other.pid_ = -1;
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !status_) terminate();
}

bool ChildProcess::stopped() const {
  if (pid_ <= 0 || status_) return false;
  std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
  std::stringstream text;
  text << in.rdbuf();
  // "pid (command) state ...": the command may hold spaces and parentheses, the state follows
  // the last ')'.
  const std::string stat = text.str();
  const std::size_t end = stat.rfind(')');
  return end != std::string::npos && end + 2 < stat.size() &&
         (stat[end + 2] == 'T' || stat[end + 2] == 't');
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

std::optional<ExitStatus> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!poll()) {
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status_;
}

void ChildProcess::request_stop() {
  // pid_ <= 0 (moved from): kill(-1) would signal every process we may signal.
  if (pid_ > 0 && !poll()) kill(pid_, SIGTERM);
}

ExitStatus ChildProcess::terminate(std::chrono::milliseconds grace) {
  if (poll()) return *status_;
  if (pid_ <= 0) return ExitStatus{};  // moved from: nothing of ours to end
  kill(pid_, SIGTERM);
  if (wait_for(grace)) return *status_;
  kill(pid_, SIGKILL);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  status_ = decode_wait_status(status);
  return *status_;
}

}  // namespace l2
