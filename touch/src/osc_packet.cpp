#include "touch/osc_packet.hpp"

#include <fmt/format.h>
#include <lo/lo_errors.h>
#include <lo/lo_lowlevel.h>

#include <cstring>

namespace l2 {
namespace {

constexpr std::size_t kBundleHeader = 16;  // "#bundle\0" and the 8-byte time tag

// lo_message is a void pointer: an owner of one, freed once.
struct OwnedMessage {
  lo_message m;
  explicit OwnedMessage(lo_message message) : m(message) {}
  ~OwnedMessage() {
    if (m) lo_message_free(m);
  }
  OwnedMessage(const OwnedMessage&) = delete;
  OwnedMessage& operator=(const OwnedMessage&) = delete;
};

std::uint32_t big_endian_u32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

// What liblo's refusal of a message means (lo_errors.h).
const char* liblo_reason(int error) {
  switch (error) {
    case LO_EINVALIDPATH:
      return "its address is not a terminated string";
    case LO_ENOTYPE:
      return "no type tags";
    case LO_EINVALIDTYPE:
      return "its type tags are not a terminated string";
    case LO_EBADTYPE:
      return "a type tag liblo does not know";
    case LO_ESIZE:
      return "its arguments do not fit its bytes";
    case LO_EINVALIDARG:
      return "an argument its bytes do not hold";
    case LO_EALLOC:
      return "out of memory";
    default:
      return "refused by liblo";
  }
}

// A number as liblo left it (host byte order), read by bytes: OSC aligns arguments to 4 bytes,
// less than lo_arg's union of 8-byte members asks for.
template <class T>
T read_arg(const void* at) {
  T v;
  std::memcpy(&v, at, sizeof v);
  return v;
}

OscArg argument(char type, const void* at) {
  OscArg out;
  out.type = type;
  switch (type) {
    case 'i':
      out.integer = read_arg<std::int32_t>(at);
      break;
    case 'h':
      out.integer = read_arg<std::int64_t>(at);
      break;
    case 'f':
      out.real = read_arg<float>(at);
      break;
    case 'd':
      out.real = read_arg<double>(at);
      break;
    case 's':
    case 'S':
      out.text = static_cast<const char*>(at);
      break;
    default:
      break;
  }
  return out;
}

// One message, decoded by liblo from a copy (its call takes a mutable pointer).
Status decode_message(std::span<const std::uint8_t> bytes, std::vector<OscMessage>& out) {
  if (static_cast<int>(out.size()) >= kMaxOscMessages)
    return Failure{fmt::format("more than {} messages", kMaxOscMessages)};
  std::vector<std::uint8_t> copy(bytes.begin(), bytes.end());
  int error = 0;
  const OwnedMessage owned(lo_message_deserialise(copy.data(), copy.size(), &error));
  const lo_message m = owned.m;
  if (!m) return Failure{fmt::format("not an OSC message: {}", liblo_reason(error))};
  OscMessage message;
  // liblo checked that the address is a terminated string inside the bytes.
  message.address.assign(reinterpret_cast<const char*>(copy.data()),
                         strnlen(reinterpret_cast<const char*>(copy.data()), copy.size()));
  const char* types = lo_message_get_types(m);
  lo_arg** argv = lo_message_get_argv(m);
  const int argc = lo_message_get_argc(m);
  for (int k = 0; k < argc; ++k) message.args.push_back(argument(types[k], argv[k]));
  out.push_back(std::move(message));
  return {};
}

Status decode_element(std::span<const std::uint8_t> bytes, int depth, std::vector<OscMessage>& out);

Status decode_bundle(std::span<const std::uint8_t> bytes, int depth, std::vector<OscMessage>& out) {
  if (depth >= kMaxOscBundleDepth)
    return Failure{fmt::format("bundles nested deeper than {}", kMaxOscBundleDepth)};
  if (bytes.size() < kBundleHeader) return Failure{"a bundle shorter than its header"};
  std::size_t at = kBundleHeader;
  for (int element = 0; at < bytes.size(); ++element) {
    if (bytes.size() - at < 4) return Failure{fmt::format("bundle element {}: no size", element)};
    const std::uint32_t size = big_endian_u32(bytes.data() + at);
    at += 4;
    if (size == 0 || size % 4 != 0 || size > bytes.size() - at)
      return Failure{
          fmt::format("bundle element {}: size {} past the datagram's end or not "
                      "a multiple of 4",
                      element, size)};
    if (Status s = decode_element(bytes.subspan(at, size), depth + 1, out); !s.ok())
      return Failure{fmt::format("bundle element {}: {}", element, s.reason())};
    at += size;
  }
  return {};
}

Status decode_element(std::span<const std::uint8_t> bytes, int depth,
                      std::vector<OscMessage>& out) {
  static constexpr char kBundle[8] = "#bundle";
  if (bytes.size() >= sizeof kBundle && std::memcmp(bytes.data(), kBundle, sizeof kBundle) == 0)
    return decode_bundle(bytes, depth, out);
  return decode_message(bytes, out);
}

}  // namespace

Result<std::vector<OscMessage>> decode_osc(std::span<const std::uint8_t> datagram) {
  if (datagram.empty() || datagram.size() % 4 != 0)
    return Failure{fmt::format("{} bytes: not a multiple of 4", datagram.size())};
  std::vector<OscMessage> messages;
  if (Status s = decode_element(datagram, 0, messages); !s.ok()) return Failure{s.reason()};
  return messages;
}

}  // namespace l2
