// What the link emulator (tools/link_emulator: hosts' links with delay and jitter, where the
// kernel has no netem) decides, without I/O: the ports a frame goes out of (a learning switch),
// how long a frame is held (a delay with jitter, drawn per frame as netem draws it), and the
// frames held until their time, released in time order. The program (tap_loop.cpp) reads and
// writes the hosts' tap devices and gives these the clock and the random numbers.
//
// Owns: the switch's table of addresses, the held frames and their buffers, the counts of
// what was carried, held and dropped.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <queue>
#include <span>
#include <utility>
#include <vector>

namespace l2::link_emulation {

using Nanoseconds = std::chrono::nanoseconds;
using Mac = std::array<std::uint8_t, 6>;

// An Ethernet header's two addresses come first: destination, then source.
inline constexpr std::size_t kEthernetHeader = 14;

// A learning switch of `ports` ports: a destination is sent to the port its address was last
// seen coming from; broadcast, multicast and addresses not yet seen go to every other port.
class LearningSwitch {
 public:
  explicit LearningSwitch(int ports) : ports_(ports) {}

  // The ports `frame`, which came in on port `in`, goes out of (its source learnt first): none
  // for a frame shorter than an Ethernet header, or whose destination is behind `in` itself.
  std::span<const int> destinations(int in, std::span<const std::uint8_t> frame);

 private:
  int ports_;
  std::vector<std::pair<Mac, int>> table_;  // one entry per host's address: a few
  std::vector<int> out_;
};

// Each frame held `delay` plus a jitter drawn uniformly from [-jitter, +jitter], never below
// zero: netem's `delay D J` with its default distribution.
struct LinkDelay {
  Nanoseconds delay{0};
  Nanoseconds jitter{0};
};

// The hold of one frame under `link`, from a 64-bit random number.
Nanoseconds hold_for(const LinkDelay& link, std::uint64_t random);

// What the held frames carried, held and dropped: the emulator's last line.
struct HeldCounts {
  std::uint64_t frames = 0;  // sent out of a port (a broadcast counts once per port)
  std::uint64_t bytes = 0;
  Nanoseconds least{Nanoseconds::max()}, most{0}, total{0};  // hold, from arrival to sending
  std::uint64_t over_limit = 0;  // dropped: `limit` frames were held already
};

// The frames held until their release time: released earliest first, frames due at the same
// time in the order they were held, so that jitter reorders frames as netem's does. At most
// `limit` frames held at once (netem's queue limit); a frame past it is dropped and counted.
class HeldFrames {
 public:
  explicit HeldFrames(std::size_t limit) : limit_(limit) {}

  // Holds a copy of `frame` for port `out` from `arrival` until `release`; false (dropped)
  // when `limit` frames are held already.
  bool hold(Nanoseconds arrival, Nanoseconds release, int out, std::span<const std::uint8_t> frame);

  // The earliest release time held, or none.
  bool empty() const { return queue_.empty(); }
  Nanoseconds next_release() const { return queue_.top().release; }
  std::size_t size() const { return queue_.size(); }

  // Sends every frame due at `now` (release <= now) through send(port, bytes), in release order.
  template <class Send>
  void release_due(Nanoseconds now, Send&& send) {
    while (!queue_.empty() && queue_.top().release <= now) {
      const Entry& top = queue_.top();
      const std::vector<std::uint8_t>& bytes = buffers_[top.buffer];
      send(top.out, std::span<const std::uint8_t>(bytes));
      count_sent(now - top.arrival, bytes.size());
      free_.push_back(top.buffer);
      queue_.pop();
    }
  }

  const HeldCounts& counts() const { return counts_; }

 private:
  struct Entry {
    Nanoseconds release;
    std::uint64_t order;
    Nanoseconds arrival;
    int out;
    std::size_t buffer;  // index into buffers_
    bool operator>(const Entry& other) const {
      return release != other.release ? release > other.release : order > other.order;
    }
  };
  void count_sent(Nanoseconds held, std::size_t bytes);

  std::size_t limit_;
  std::uint64_t next_order_ = 0;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue_;
  // Frame buffers reused once sent, so that holding a frame allocates only while the number
  // held grows past what it has been.
  std::vector<std::vector<std::uint8_t>> buffers_;
  std::vector<std::size_t> free_;
  HeldCounts counts_;
};

}  // namespace l2::link_emulation
