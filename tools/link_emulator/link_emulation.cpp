#include "link_emulation.hpp"

#include <algorithm>
#include <cstring>

namespace l2::link_emulation {

namespace {

Mac address_at(std::span<const std::uint8_t> frame, std::size_t offset) {
  Mac mac;
  std::memcpy(mac.data(), frame.data() + offset, mac.size());
  return mac;
}

// The group bit, the first octet's lowest: broadcast and multicast alike.
bool group_address(const Mac& mac) {
  return (mac[0] & 1) != 0;
}

}  // namespace

std::span<const int> LearningSwitch::destinations(int in, std::span<const std::uint8_t> frame) {
  out_.clear();
  if (frame.size() < kEthernetHeader) return out_;
  const Mac destination = address_at(frame, 0), source = address_at(frame, 6);
  if (!group_address(source)) {
    const auto known = std::find_if(table_.begin(), table_.end(),
                                    [&](const auto& entry) { return entry.first == source; });
    if (known == table_.end()) {
      table_.emplace_back(source, in);
    } else {
      known->second = in;  // a host that moved to another port
    }
  }
  if (!group_address(destination)) {
    const auto known = std::find_if(table_.begin(), table_.end(),
                                    [&](const auto& entry) { return entry.first == destination; });
    if (known != table_.end()) {
      if (known->second != in) out_.push_back(known->second);
      return out_;
    }
  }
  for (int port = 0; port < ports_; ++port) {
    if (port != in) out_.push_back(port);
  }
  return out_;
}

Nanoseconds hold_for(const LinkDelay& link, std::uint64_t random) {
  const std::int64_t jitter = link.jitter.count();
  if (jitter <= 0) return link.delay;
  const auto span = static_cast<std::uint64_t>(jitter) * 2 + 1;
  const std::int64_t offset = static_cast<std::int64_t>(random % span) - jitter;
  return std::max(Nanoseconds{0}, link.delay + Nanoseconds{offset});
}

bool HeldFrames::hold(Nanoseconds arrival, Nanoseconds release, int out,
                      std::span<const std::uint8_t> frame) {
  if (queue_.size() >= limit_) {
    ++counts_.over_limit;
    return false;
  }
  std::size_t buffer;
  if (free_.empty()) {
    buffer = buffers_.size();
    buffers_.emplace_back();
  } else {
    buffer = free_.back();
    free_.pop_back();
  }
  buffers_[buffer].assign(frame.begin(), frame.end());
  queue_.push(Entry{release, next_order_++, arrival, out, buffer});
  return true;
}

void HeldFrames::count_sent(Nanoseconds held, std::size_t bytes) {
  ++counts_.frames;
  counts_.bytes += bytes;
  counts_.least = std::min(counts_.least, held);
  counts_.most = std::max(counts_.most, held);
  counts_.total += held;
}

}  // namespace l2::link_emulation
