// The frame delta decoder (dvi_link/frame_delta.hpp), what a column and the compositing server
// apply to bytes from a peer: the first two bytes choose a frame of 1..64 x 1..64, the rest is
// one message, applied twice (the second builds on the first). A refusal is one line and
// changes nothing; an accepted message is re-encoded and must give the same frame.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "dvi_link/frame_delta.hpp"
#include "fuzz_check.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int width = 1 + data[0] % 64, height = 1 + data[1] % 64;
  const std::vector<std::uint8_t> message(data + 2, data + size);
  l2::FrameDeltaDecoder decoder(width, height);
  for (int round = 0; round < 2; ++round) {
    const std::vector<std::uint8_t> before(decoder.frame().begin(), decoder.frame().end());
    const l2::Status s = decoder.decode(message);
    if (!s.ok()) {
      l2::fuzz::require_one_line(s.reason(), "a refusal is one line");
      require(std::equal(before.begin(), before.end(), decoder.frame().begin()),
              "a refused message changes nothing");
      return 0;
    }
    require(message.size() <= l2::max_frame_delta_bytes(width, height),
            "an accepted message is no larger than a frame's largest");
  }
  // What was rebuilt, sent again from black, arrives the same.
  l2::FrameDeltaEncoder encoder(width, height, l2::LinkCodec::Lz4);
  l2::FrameDeltaDecoder again(width, height);
  require(again.decode(encoder.encode(decoder.frame())).ok(), "a fresh encoding decodes");
  require(std::equal(again.frame().begin(), again.frame().end(), decoder.frame().begin()),
          "a fresh encoding gives the same frame");
  return 0;
}
