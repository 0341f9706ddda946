// The words of one line, each checked as it is taken: what every control message decoder of
// balance/ reads its line with, and l2wall its window commands.
#pragma once

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "balance/control_messages.hpp"

namespace l2 {

// Reads the space-separated words of one line, each checked as it is taken.
class Words {
 public:
  // `kind` names the line in errors: "control line 'WANT x': ...".
  explicit Words(std::string_view line, std::string_view kind = "control line")
      : line_(line), rest_(line), kind_(kind) {}

  void keyword(std::string_view want) {
    if (next() != want) fail(fmt::format("not a {} message", want));
  }
  long long integer(const char* what, long long min, long long max) {
    const std::string_view w = next();
    long long v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || v < min || v > max) {
      fail(fmt::format("{} must be an integer {}..{}, got '{}'", what, min, max, clip(w)));
    }
    return v;
  }
  double seconds() {
    const std::string_view w = next();
    double v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v) || v < 0) {
      fail(fmt::format("a render time must be seconds >= 0, got '{}'", clip(w)));
    }
    return v;
  }
  // Takes the next word if it is `want`.
  bool optional_keyword(std::string_view want) {
    const std::string_view before = rest_;
    if (next() == want) return true;
    rest_ = before;
    return false;
  }
  // The next word as it is (a payload the caller checks).
  std::string_view word() { return next(); }
  void end() {
    if (!next().empty()) fail("more words than its count says");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw ControlError(fmt::format("{} '{}': {}", kind_, clip(line_), why));
  }

 private:
  static std::string clip(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 40)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
    return s.size() > 40 ? out + "..." : out;
  }
  std::string_view next() {
    while (!rest_.empty() && rest_.front() == ' ') rest_.remove_prefix(1);
    const std::size_t n = std::min(rest_.find(' '), rest_.size());
    const std::string_view w = rest_.substr(0, n);
    rest_.remove_prefix(n);
    return w;
  }
  std::string_view line_, rest_, kind_;
};

// The largest frame number a line may carry.
inline constexpr long long kMaxFrame = 1LL << 30;

}  // namespace l2
