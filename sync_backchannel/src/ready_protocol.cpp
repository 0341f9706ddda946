#include "sync_backchannel/ready_protocol.hpp"

#include <fmt/format.h>

namespace l2 {
namespace {

constexpr std::string_view kReadyVerb = "READY";
constexpr std::string_view kSyncVerb = "SYNC?";
constexpr std::size_t kVerbBytes = 5;
constexpr std::size_t kDigitsAt = 6;
constexpr std::size_t kHexAt = 13;

std::string_view verb(MessageKind kind) {
  return kind == MessageKind::Ready ? kReadyVerb : kSyncVerb;
}

bool is_digit(std::uint8_t b) {
  return b >= '0' && b <= '9';
}
bool is_upper_hex(std::uint8_t b) {
  return is_digit(b) || (b >= 'A' && b <= 'F');
}
int hex_value(std::uint8_t b) {
  return is_digit(b) ? b - '0' : b - 'A' + 10;
}

}  // namespace

std::uint8_t crc8(std::string_view bytes) {
  std::uint8_t crc = 0;
  for (char c : bytes) {
    crc ^= static_cast<std::uint8_t>(c);
    for (int bit = 0; bit < 8; ++bit) {
      crc = static_cast<std::uint8_t>((crc & 0x80) ? (crc << 1) ^ 0x07 : crc << 1);
    }
  }
  return crc;
}

std::string format_message(MessageKind kind, std::uint64_t frame) {
  std::string body = fmt::format("{} {:06d}", verb(kind), frame % kFrameModulus);
  return fmt::format("{} {:02X}\r\n", body, crc8(body));
}

std::string to_string(const Message& message) {
  return fmt::format("{} {:06d}", verb(message.kind), message.frame);
}

std::vector<Message> MessageParser::feed(std::span<const std::uint8_t> bytes) {
  std::vector<Message> out;
  feed(bytes, [&](const Message& m) { out.push_back(m); });
  return out;
}

std::vector<Message> MessageParser::feed(std::string_view bytes) {
  return feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

// Whether `byte` may sit at position length_ of the message begun in line_.
bool MessageParser::fits(std::uint8_t byte) const {
  const std::size_t at = length_;
  if (at < kVerbBytes) {
    const std::string_view v = line_[0] == 'R' ? kReadyVerb : kSyncVerb;
    return byte == static_cast<std::uint8_t>(v[at]);
  }
  if (at == kVerbBytes || at == kHexAt - 1) return byte == ' ';
  if (at < kHexAt - 1) return is_digit(byte);
  if (at < kHexAt + 2) return is_upper_hex(byte);
  if (at == kHexAt + 2) return byte == '\r';
  return byte == '\n';
}

bool MessageParser::consume(std::uint8_t byte) {
  if (length_ > 0 && !fits(byte)) {
    // The partial message is lost; the offending byte may itself start the next one.
    counts_.noise_bytes += length_;
    ++counts_.resyncs;
    length_ = 0;
  }
  if (length_ == 0 && byte != 'R' && byte != 'S') {
    ++counts_.noise_bytes;
    return false;
  }
  line_[length_++] = byte;
  if (length_ < kMessageBytes) return false;
  length_ = 0;
  return finish();
}

bool MessageParser::finish() {
  const std::string_view body(reinterpret_cast<const char*>(line_.data()), kChecksummedBytes);
  const int sent = hex_value(line_[kHexAt]) * 16 + hex_value(line_[kHexAt + 1]);
  if (sent != crc8(body)) {
    ++counts_.bad_checksums;
    return false;
  }
  std::uint32_t frame = 0;
  for (std::size_t i = kDigitsAt; i < kDigitsAt + 6; ++i) {
    frame = frame * 10 + static_cast<std::uint32_t>(line_[i] - '0');
  }
  last_ = Message{line_[0] == 'R' ? MessageKind::Ready : MessageKind::SyncRequest, frame};
  ++counts_.messages;
  return true;
}

}  // namespace l2
