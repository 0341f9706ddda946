#include "displays/xvfb_server.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace l2::testing {

namespace {

std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

// Reads what Xvfb writes to the -displayfd pipe: the display number, once it accepts clients.
std::string read_display_number(int fd, std::chrono::seconds timeout) {
  std::string text;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (text.find('\n') == std::string::npos) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
    char buf[32];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  if (text.find('\n') == std::string::npos) return {};
  return text.substr(0, text.find('\n'));
}

}  // namespace

bool XvfbServer::installed() {
  return !find_on_path("Xvfb").empty();
}

XvfbServer::XvfbServer(int width, int height)
    : XvfbServer("Xvfb",
                 {"-screen", "0", std::to_string(width) + "x" + std::to_string(height) + "x24",
                  "-nolisten", "tcp"}) {
  setenv("DISPLAY", display_.c_str(), 1);
}

XvfbServer::XvfbServer(const std::string& name, const std::vector<std::string>& server_args) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(name + ": cannot make a pipe");
  // Keep the write end off fd 3, so the dup2 below really makes a fresh, inheritable fd 3.
  const int high = fcntl(fds[1], F_DUPFD_CLOEXEC, 10);
  close(fds[1]);
  fds[1] = high;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 3);  // fd 3 survives exec, the pipe not
  const int devnull = open("/dev/null", O_WRONLY | O_CLOEXEC);
  posix_spawn_file_actions_adddup2(&actions, devnull, 2);  // the server's chatter stays out of logs
  const std::string program = find_on_path(name);
  std::vector<std::string> args = {program, "-displayfd", "3"};
  args.insert(args.end(), server_args.begin(), server_args.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int rc = program.empty()
                     ? ENOENT
                     : posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  close(devnull);
  if (rc != 0) {
    close(fds[0]);
    throw std::runtime_error(name + ": cannot start it");
  }
  const std::string number = read_display_number(fds[0], std::chrono::seconds(20));
  close(fds[0]);
  if (number.empty()) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    throw std::runtime_error(name + ": did not report a display within 20 s");
  }
  display_ = ":" + number;
}

XvfbServer::~XvfbServer() {
  kill(pid_, SIGTERM);
  int status = 0;
  for (int i = 0; i < 100; ++i) {
    if (waitpid(pid_, &status, WNOHANG) == pid_) return;
    usleep(20000);
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, &status, 0);
}

}  // namespace l2::testing
