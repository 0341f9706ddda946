#include "vizserver/display_stream.hpp"

#include <fmt/format.h>

namespace l2::viz {
std::array<std::uint8_t, kHeaderBytes + 12> encode(const Listening& m) {
  MessageWriter<12> w(Kind::Listening);
  return w.u32(m.port).u32(m.display_count).u32(m.pipeserver_count).done();
}

std::array<std::uint8_t, kHeaderBytes + 16> encode(const DisplayHeader& m) {
  MessageWriter<16> w(Kind::Display, m.pixel_bytes());
  return w.u32(m.frame).u32(m.display).u32(m.width).u32(m.height).done();
}

std::array<std::uint8_t, kHeaderBytes + 20> encode(const Shown& m) {
  MessageWriter<20> w(Kind::Shown);
  return w.u32(m.frame)
      .u32(m.display_count)
      .u32(m.tiles)
      .u32(m.clipped_rows)
      .u32(m.missing_display_rows)
      .done();
}

std::array<std::uint8_t, kHeaderBytes + 4> encode_lost(std::uint32_t pipeserver) {
  MessageWriter<4> w(Kind::Lost);
  return w.u32(pipeserver).done();
}

Listening decode_listening(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  Listening l;
  l.port = r.u32();
  l.display_count = r.u32();
  l.pipeserver_count = r.u32();
  return l;
}

DisplayHeader decode_display(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  DisplayHeader d;
  d.frame = r.u32();
  d.display = r.u32();
  d.width = r.u32();
  d.height = r.u32();
  return d;
}

Shown decode_shown(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  Shown s;
  s.frame = r.u32();
  s.display_count = r.u32();
  s.tiles = r.u32();
  s.clipped_rows = r.u32();
  s.missing_display_rows = r.u32();
  return s;
}

Status validate(const DisplayHeader& d, std::uint32_t payload_bytes) {
  if (d.width < 1 || d.width > kMaxDisplaySide || d.height < 1 || d.height > kMaxDisplaySide) {
    return Failure{fmt::format("DISPLAY of {}x{} pixels, each side must be 1..{}", d.width,
                               d.height, kMaxDisplaySide)};
  }
  if (payload_bytes != 16 + d.pixel_bytes()) {
    return Failure{fmt::format("DISPLAY {}x{} needs a payload of {} bytes, header says {}", d.width,
                               d.height, 16 + d.pixel_bytes(), payload_bytes)};
  }
  return {};
}

}  // namespace l2::viz
