// What every harness uses to report a broken promise: a message on stderr, then abort(), which
// libFuzzer reports as a crash and saves the input for.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace l2::fuzz {

inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: broken promise: %s\n", what);
  std::abort();
}

// Errors of bad input are one line (the project's rule): no line break, not empty.
inline void require_one_line(std::string_view message, const char* what) {
  require(!message.empty() && message.find('\n') == std::string_view::npos, what);
}

}  // namespace l2::fuzz
