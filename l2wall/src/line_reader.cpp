#include "line_reader.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>

namespace l2 {

std::vector<std::string> LineReader::take() {
  std::vector<std::string> lines;
  while (!ended_) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 0) <= 0) break;
    char buffer[4096];
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ended_ = true;  // end of file, or a descriptor that cannot be read
      break;
    }
    for (ssize_t i = 0; i < n; ++i) {
      if (buffer[i] == '\n') {
        lines.push_back(std::move(pending_));
        pending_.clear();
      } else if (pending_.size() < kMaxLine) {
        pending_ += buffer[i];
      }
    }
  }
  return lines;
}

}  // namespace l2
