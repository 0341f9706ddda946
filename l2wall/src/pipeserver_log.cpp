#include "pipeserver_log.hpp"

#include <utility>

namespace l2 {

PipeserverLogLine parse_pipeserver_log_line(const std::string& line) {
  PipeserverLogLine l;
  if (std::sscanf(line.c_str(), "frame %d render_ms %lf wait_ms %lf retries %d", &l.frame,
                  &l.render_ms, &l.wait_ms, &l.retries) == 4) {
    l.kind = PipeserverLogLine::Kind::Frame;
  } else if (line.rfind("done ", 0) == 0) {
    l.kind = PipeserverLogLine::Kind::Done;
    l.done = line.substr(5);
  } else if (line.rfind("renderer ", 0) == 0) {
    l.kind = PipeserverLogLine::Kind::Renderer;
    l.renderer = line.substr(9);
  }
  return l;
}

PipeserverLogTail::~PipeserverLogTail() {
  if (file_) std::fclose(file_);
}

PipeserverLogTail::PipeserverLogTail(PipeserverLogTail&& other) noexcept
    : path_(std::move(other.path_)),
      file_(std::exchange(other.file_, nullptr)),
      partial_(std::move(other.partial_)) {}

bool PipeserverLogTail::next_line(std::string& line) {
  if (!file_) file_ = std::fopen(path_.c_str(), "r");
  if (!file_) return false;
  std::clearerr(file_);  // read on past the end of the last look
  for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) {
    if (c != '\n') {
      partial_ += static_cast<char>(c);
      continue;
    }
    line = std::exchange(partial_, {});
    return true;
  }
  return false;
}

}  // namespace l2
