// The link emulator's edge: the hosts' tap devices (each host's end of its link, in its network
// namespace; the emulator holds the other end), read as they become readable, every frame held
// as link_emulation.hpp decides and written to its destination's tap when due.
//
// Owns: the taps' descriptors, the clock, the random numbers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "link_emulation.hpp"

namespace l2::link_emulation {

struct TapLoopOptions {
  std::vector<std::string> taps;  // persistent tap devices (`ip tuntap add ... mode tap`)
  LinkDelay link;
  std::size_t limit = 10000;  // frames held at once
  std::uint64_t seed = 1;
};

struct TapLoopEnd {
  HeldCounts held;
  std::uint64_t too_short = 0;  // read frames shorter than an Ethernet header
  std::uint64_t not_taken = 0;  // frames a host's tap did not take (its queue full)
  std::string gone;             // a tap that went away (its namespace deleted), which ended it
};

// Attaches to every tap (a one-line failure naming the tap otherwise), calls `ready` once all
// are attached, then carries frames until a stop signal (base/stop_signals.hpp) is recorded or
// a tap goes away.
Result<TapLoopEnd> carry_frames(const TapLoopOptions& options, void (*ready)());

// The last line: what was carried, how long it was held, what was dropped.
std::string describe(const TapLoopOptions& options, const TapLoopEnd& end);

}  // namespace l2::link_emulation
