#include "vizserver/display_stream.hpp"

#include <fmt/format.h>

namespace l2::viz {
namespace {

constexpr std::size_t kMaxDisplayPayload =
    16 + std::size_t{kMaxDisplaySide} * kMaxDisplaySide * 3;  // 768 MiB: fits the u32 length

template <std::size_t Fixed>
std::array<std::uint8_t, kHeaderBytes + Fixed> start(StreamKind kind, std::size_t extra = 0) {
  std::array<std::uint8_t, kHeaderBytes + Fixed> out{};
  put_message_header(out.data(), static_cast<std::uint16_t>(kind), Fixed + extra);
  return out;
}

bool stream_kind(std::uint16_t k) {
  return k == 6 || (k >= 16 && k <= 18);
}

}  // namespace

std::size_t fixed_bytes(StreamKind kind) {
  switch (kind) {
    case StreamKind::Listening:
      return 12;
    case StreamKind::Display:
      return 16;
    case StreamKind::Shown:
      return 20;
    case StreamKind::Error:
      return 0;
  }
  return 0;
}

const char* kind_name(StreamKind kind) {
  switch (kind) {
    case StreamKind::Listening:
      return "LISTENING";
    case StreamKind::Display:
      return "DISPLAY";
    case StreamKind::Shown:
      return "SHOWN";
    case StreamKind::Error:
      return "ERROR";
  }
  return "?";
}

std::array<std::uint8_t, kHeaderBytes + 12> encode(const Listening& m) {
  auto out = start<12>(StreamKind::Listening);
  put_u32(out.data() + 12, m.port);
  put_u32(out.data() + 16, m.display_count);
  put_u32(out.data() + 20, m.server_count);
  return out;
}

std::array<std::uint8_t, kHeaderBytes + 16> encode(const DisplayHeader& m) {
  auto out = start<16>(StreamKind::Display, m.pixel_bytes());
  put_u32(out.data() + 12, m.frame);
  put_u32(out.data() + 16, m.display);
  put_u32(out.data() + 20, m.width);
  put_u32(out.data() + 24, m.height);
  return out;
}

std::array<std::uint8_t, kHeaderBytes + 20> encode(const Shown& m) {
  auto out = start<20>(StreamKind::Shown);
  put_u32(out.data() + 12, m.frame);
  put_u32(out.data() + 16, m.display_count);
  put_u32(out.data() + 20, m.tiles);
  put_u32(out.data() + 24, m.clipped_rows);
  put_u32(out.data() + 28, m.missing_display_rows);
  return out;
}

std::variant<StreamHeader, std::string> decode_stream_header(
    std::span<const std::uint8_t, kHeaderBytes> b) {
  const std::uint32_t magic = get_u32(b.data());
  if (magic != kMagic) {
    return fmt::format("bad magic 0x{:08x}, expected 0x{:08x} (not a vizserver?)", magic, kMagic);
  }
  const std::uint16_t version = get_u16(b.data() + 4);
  if (version != kVersion) {
    return fmt::format("protocol version {}, this build speaks {}", version, kVersion);
  }
  const std::uint16_t raw_kind = get_u16(b.data() + 6);
  if (!stream_kind(raw_kind)) {
    return fmt::format("message kind {} is not one of the display stream", raw_kind);
  }
  const StreamHeader h{static_cast<StreamKind>(raw_kind), get_u32(b.data() + 8)};
  const std::size_t fixed = fixed_bytes(h.kind);
  const std::size_t max = h.kind == StreamKind::Display ? kMaxDisplayPayload
                          : h.kind == StreamKind::Error ? kMaxErrorText
                                                        : fixed;
  if (h.payload_bytes < fixed || h.payload_bytes > max) {
    return fmt::format("{} payload of {} bytes, allowed {}..{}", kind_name(h.kind), h.payload_bytes,
                       fixed, max);
  }
  return h;
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

std::optional<std::string> validate(const DisplayHeader& d, std::uint32_t payload_bytes) {
  if (d.width < 1 || d.width > kMaxDisplaySide || d.height < 1 || d.height > kMaxDisplaySide) {
    return fmt::format("DISPLAY of {}x{} pixels, each side must be 1..{}", d.width, d.height,
                       kMaxDisplaySide);
  }
  if (payload_bytes != 16 + d.pixel_bytes()) {
    return fmt::format("DISPLAY {}x{} needs a payload of {} bytes, header says {}", d.width,
                       d.height, 16 + d.pixel_bytes(), payload_bytes);
  }
  return std::nullopt;
}

}  // namespace l2::viz
