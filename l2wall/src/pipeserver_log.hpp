// A pipeserver's log (OUT/pipeserver-<i>.log, pipeserver --report): first the renderer it decided
// on ("renderer egl (llvmpipe ...; --renderer egl)"), then a line per frame ("frame K render_ms R
// wait_ms W retries N ...") and, once it ends well, its back-channel totals ("done ..."). Read
// whole for the report at the end, and as it grows for the control page.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace l2 {

struct PipeserverLogLine {
  enum class Kind { Renderer, Frame, Done, Other };
  Kind kind = Kind::Other;
  int frame = 0;
  double render_ms = 0, wait_ms = 0;
  int retries = 0;
  std::string done;      // Done: the totals after "done "
  std::string renderer;  // Renderer: what follows "renderer "
};

PipeserverLogLine parse_pipeserver_log_line(const std::string& line);

// The lines a log gained since the last look; only whole lines (the pipeserver may be writing
// one). A log not there yet is read from its start once it is.
class PipeserverLogTail {
 public:
  explicit PipeserverLogTail(std::string path) : path_(std::move(path)) {}
  ~PipeserverLogTail();
  PipeserverLogTail(PipeserverLogTail&& other) noexcept;
  PipeserverLogTail(const PipeserverLogTail&) = delete;
  PipeserverLogTail& operator=(const PipeserverLogTail&) = delete;
  PipeserverLogTail& operator=(PipeserverLogTail&&) = delete;

  // Calls `each` for every whole new line.
  template <class F>
  void read_new(F&& each) {
    std::string line;
    while (next_line(line)) each(parse_pipeserver_log_line(line));
  }

 private:
  bool next_line(std::string& line);
  std::string path_;
  std::FILE* file_ = nullptr;
  std::string partial_;  // the start of a line still being written
};

}  // namespace l2
