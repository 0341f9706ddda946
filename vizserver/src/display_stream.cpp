#include "vizserver/display_stream.hpp"

#include <fmt/format.h>

namespace l2::viz {
std::array<std::uint8_t, kHeaderBytes + 12> encode(const Listening& m) {
  auto out = message_start<12>(Kind::Listening);
  put_u32(out.data() + 12, m.port);
  put_u32(out.data() + 16, m.display_count);
  put_u32(out.data() + 20, m.pipeserver_count);
  return out;
}

std::array<std::uint8_t, kHeaderBytes + 16> encode(const DisplayHeader& m) {
  auto out = message_start<16>(Kind::Display, m.pixel_bytes());
  put_u32(out.data() + 12, m.frame);
  put_u32(out.data() + 16, m.display);
  put_u32(out.data() + 20, m.width);
  put_u32(out.data() + 24, m.height);
  return out;
}

std::array<std::uint8_t, kHeaderBytes + 20> encode(const Shown& m) {
  auto out = message_start<20>(Kind::Shown);
  put_u32(out.data() + 12, m.frame);
  put_u32(out.data() + 16, m.display_count);
  put_u32(out.data() + 20, m.tiles);
  put_u32(out.data() + 24, m.clipped_rows);
  put_u32(out.data() + 28, m.missing_display_rows);
  return out;
}

std::array<std::uint8_t, kHeaderBytes + 4> encode_lost(std::uint32_t pipeserver) {
  auto out = message_start<4>(Kind::Lost);
  put_u32(out.data() + 12, pipeserver);
  return out;
}

Listening decode_listening(std::span<const std::uint8_t> f) {
  return {get_u32(f.data()), get_u32(f.data() + 4), get_u32(f.data() + 8)};
}

DisplayHeader decode_display(std::span<const std::uint8_t> f) {
  return {get_u32(f.data()), get_u32(f.data() + 4), get_u32(f.data() + 8), get_u32(f.data() + 12)};
}

Shown decode_shown(std::span<const std::uint8_t> f) {
  return {get_u32(f.data()), get_u32(f.data() + 4), get_u32(f.data() + 8), get_u32(f.data() + 12),
          get_u32(f.data() + 16)};
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
