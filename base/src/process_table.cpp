#include "base/process_table.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "base/fd.hpp"

namespace l2 {
namespace {

// The whole of a /proc file, or what could be read of it: empty for a process that has gone.
// By read(2): a process ending mid-read fails it with ESRCH, which std::filebuf would throw.
std::string read_whole(const std::string& path) {
  const Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  std::string text;
  if (!fd) return text;
  char chunk[4096];
  for (;;) {
    const ssize_t n = ::read(fd.get(), chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return text;
    text.append(chunk, static_cast<std::size_t>(n));
  }
}

}  // namespace

char process_state(pid_t pid) {
  if (pid <= 0) return '\0';
  // "pid (command) state ...": the command may hold spaces and parentheses, the state follows
  // the last ')'.
  const std::string stat = read_whole("/proc/" + std::to_string(pid) + "/stat");
  const std::size_t end = stat.rfind(')');
  return end != std::string::npos && end + 2 < stat.size() ? stat[end + 2] : '\0';
}

bool process_running(pid_t pid) {
  const char state = process_state(pid);
  return state != '\0' && state != 'Z';
}

std::string process_command_line(pid_t pid) {
  return pid > 0 ? read_whole("/proc/" + std::to_string(pid) + "/cmdline") : std::string();
}

std::vector<pid_t> processes_with_command_line(std::string_view needle) {
  std::vector<pid_t> pids;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string n = e.path().filename().string();
    if (n.empty() || n.find_first_not_of("0123456789") != std::string::npos) continue;
    // A process that ended since the listing reads as an empty command line.
    if (read_whole(e.path().string() + "/cmdline").find(needle) != std::string::npos)
      pids.push_back(static_cast<pid_t>(std::stol(n)));
  }
  return pids;
}

}  // namespace l2
