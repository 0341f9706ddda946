// TUIO over UDP as `l2wall run --tuio` takes it (touch/): datagrams, split from the input at
// each "|~|", decoded as OSC (liblo), their cursor messages made into frames, the frames into
// window commands on two fixed windows of a 1300x980 canvas. A datagram refused is a one-line
// reason; a frame holds at most kMaxTouchCursors fingers, each within 0..1; every command is
// one live_windows.cpp takes (a move within its limits, a raise).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string_view>

#include "fuzz_check.hpp"
#include "tilelayout/session_file.hpp"
#include "touch/gestures.hpp"
#include "touch/osc_packet.hpp"
#include "touch/tuio_cursors.hpp"

namespace {

using l2::fuzz::require;

void check_command(const std::string& c) {
  int id = 0, x = 0, y = 0, w = 0, h = 0;
  char end = 0;
  if (std::sscanf(c.c_str(), "move %d %d %d %d %d%c", &id, &x, &y, &w, &h, &end) == 5) {
    require(id == 1 || id == 2, "a move names a window under a finger");
    require(std::abs(x) <= l2::kWindowReach && std::abs(y) <= l2::kWindowReach,
            "a move stays within a window's reach");
    require(w >= 1 && h >= 1 && w <= l2::kMaxWindowSide && h <= l2::kMaxWindowSide,
            "a move's sides are 1..16384");
    return;
  }
  require(std::sscanf(c.c_str(), "raise %d%c", &id, &end) == 1 && (id == 1 || id == 2),
          "a command is a move or a raise of a window under a finger");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<l2::WindowPlace> windows{{1, {100, 100, 400, 300}},
                                                    {2, {300, 250, 500, 400}}};
  l2::TuioCursors cursors;
  l2::Gestures gestures(1300, 980);
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::size_t at = 0;
  while (at <= input.size()) {
    const std::size_t cut = std::min(input.find("|~|", at), input.size());
    const auto datagram = std::span<const std::uint8_t>(data + at, cut - at);
    at = cut + 3;
    const auto messages = l2::decode_osc(datagram);
    if (!messages.ok()) {
      l2::fuzz::require_one_line(messages.reason(), "a refused datagram is one line");
      continue;
    }
    require(messages->size() <= static_cast<std::size_t>(l2::kMaxOscMessages),
            "a datagram holds at most kMaxOscMessages messages");
    for (const l2::OscMessage& m : *messages) {
      const auto f = cursors.take(m);
      if (!f) continue;
      require(f->cursors.size() <= static_cast<std::size_t>(l2::kMaxTouchCursors),
              "a frame holds at most kMaxTouchCursors fingers");
      for (const l2::Cursor& c : f->cursors)
        require(c.id >= 0 && c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1,
                "a finger has an id 0 or more and a place within 0..1");
      for (const std::string& c : gestures.take(*f, windows)) check_command(c);
    }
  }
  return 0;
}
