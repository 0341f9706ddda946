// The back-channel as MPI messages (the MPI backend of ready_channel.hpp): the 17-byte READY
// and SYNC? lines of docs/ready-protocol.md, one line per message, parsed by the same parser,
// with the same waits, retries and counts as the serial line.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "sync_backchannel/back_channel.hpp"
#include "sync_backchannel/ready_channel.hpp"
#include "sync_backchannel/ready_protocol.hpp"

namespace l2 {

class MpiReadyChannel final : public ReadyChannel {
 public:
  // `peer`: the rank at the other end (the coordinator for a host, a host for the
  // coordinator); `name` is how a wait that timed out names the line ("MPI rank 0").
  MpiReadyChannel(int peer, std::string name) : peer_(peer), name_(std::move(name)) {}

  bool send_ready(std::uint64_t frame) override;
  int serve(std::chrono::milliseconds duration) override;
  WaitResult wait_ready(std::uint64_t expected, std::chrono::milliseconds timeout,
                        int retries) override;
  void send_sync_request(std::uint64_t expected) override;
  const BackChannelCounts& counts() const override;

 private:
  // Takes every line waiting under `tag` into the inbox; false when there was none.
  bool pump(int tag);
  bool accept(std::uint32_t frame, std::uint32_t expected);

  int peer_;
  std::string name_;
  MessageParser parser_;
  std::deque<Message> inbox_;
  std::optional<std::uint32_t> last_sent_;
  std::optional<std::uint32_t> last_accepted_;
  mutable BackChannelCounts counts_;
};

}  // namespace l2
