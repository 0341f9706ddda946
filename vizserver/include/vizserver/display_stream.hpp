// The display stream (docs/vizserver-protocol.md): the compositing server, running as its own
// process, hands every swapped frame's display pictures to one watcher (l2wall) over TCP, so
// the run can keep frames and compare them byte for byte with the DVI path. Same 12-byte header
// as the pipeserver protocol (magic, version, kind, length; little-endian), its own kinds:
//
//   LISTENING  server -> watcher, first: the port pipeservers connect to (no race on port 0)
//   DISPLAY    server -> watcher: one display picture of one frame
//   SHOWN      server -> watcher: every DISPLAY of that frame was sent (counts of the frame)
//   ERROR      server -> watcher: why the server ends (its failure line), then it closes
//   LOST       watcher -> server: a pipeserver died and the run goes on without it
//              (--survive-loss): frames from then on do not wait for it
//
// Pure encoding and validation here; DisplaySender and DisplayWatcher do the I/O.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "viz_link/wire.hpp"

namespace l2::viz {

struct Listening {
  std::uint32_t port = 0;
  std::uint32_t display_count = 0;
  std::uint32_t pipeserver_count = 0;
};

// One display picture: width*height RGB pixels follow, rows top to bottom, no padding.
struct DisplayHeader {
  std::uint32_t frame = 0;
  std::uint32_t display = 0;
  std::uint32_t width = 0, height = 0;
  std::size_t pixel_bytes() const { return std::size_t{width} * height * 3; }
};

struct Shown {
  std::uint32_t frame = 0;
  std::uint32_t display_count = 0;  // DISPLAY messages sent for this frame, one per display
  std::uint32_t tiles = 0;
  std::uint32_t clipped_rows = 0;          // spec §3 clips of the frame
  std::uint32_t missing_display_rows = 0;  // rows for displays that do not exist
};

std::array<std::uint8_t, kHeaderBytes + 12> encode(const Listening& m);
std::array<std::uint8_t, kHeaderBytes + 16> encode(const DisplayHeader& m);
std::array<std::uint8_t, kHeaderBytes + 20> encode(const Shown& m);
// LOST: the pipeserver's id.
std::array<std::uint8_t, kHeaderBytes + 4> encode_lost(std::uint32_t pipeserver);

// Headers of the stream are read with decode_header(bytes, Protocol::DisplayStream) or a
// MessageHead of that protocol (wire.hpp): a DISPLAY's length is bounded by kMaxDisplaySide
// there, and checked again with the fixed part by validate().
Listening decode_listening(std::span<const std::uint8_t> fixed);
DisplayHeader decode_display(std::span<const std::uint8_t> fixed);
Shown decode_shown(std::span<const std::uint8_t> fixed);
// A DISPLAY whose sides are outside 1..kMaxDisplaySide or whose length is not 16 + w*h*3.
Status validate(const DisplayHeader& d, std::uint32_t payload_bytes);

}  // namespace l2::viz
