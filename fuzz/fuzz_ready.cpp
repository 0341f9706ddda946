// The READY parser of the serial back-channel (spec §6.3) on arbitrary bytes, fed in pieces of
// the sizes the input's first byte picks: every byte is accounted for, and every message it
// finds is one that format_message writes back the same.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fuzz_check.hpp"
#include "sync_backchannel/ready_protocol.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t piece = 1 + data[0] % 32;
  const std::span<const std::uint8_t> bytes(data + 1, size - 1);
  l2::MessageParser parser;
  std::vector<l2::Message> found;
  for (std::size_t at = 0; at < bytes.size(); at += piece) {
    parser.feed(bytes.subspan(at, std::min(piece, bytes.size() - at)),
                [&](const l2::Message& m) { found.push_back(m); });
  }
  const l2::ParserCounts& c = parser.counts();
  require(c.messages == found.size(), "every message counted is handed over");
  require((c.messages + c.bad_checksums) * l2::kMessageBytes + c.noise_bytes + parser.pending() ==
              bytes.size(),
          "messages, bad checksums, noise and the pending tail account for every byte");
  for (const l2::Message& m : found) {
    require(m.frame < l2::kFrameModulus, "frame numbers are below the modulus");
    l2::MessageParser again;
    const std::vector<l2::Message> back = again.feed(l2::format_message(m.kind, m.frame));
    require(back.size() == 1 && back[0] == m, "a message found is one format_message writes");
  }
  return 0;
}
