// Whole lines from a descriptor (stdin) as they come, never waiting: a run reads commands
// between frames without holding a frame up for a person typing.
#pragma once

#include <string>
#include <vector>

namespace l2 {

class LineReader {
 public:
  explicit LineReader(int fd) : fd_(fd) {}
  // The whole lines read so far, without their newlines; a line longer than kMaxLine is cut
  // there (a command is a few words). Nothing more once the descriptor reached its end.
  std::vector<std::string> take();

  static constexpr std::size_t kMaxLine = 256;

 private:
  int fd_;
  bool ended_ = false;
  std::string pending_;  // the start of a line not ended yet
};

}  // namespace l2
