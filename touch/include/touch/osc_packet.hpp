// OSC packets as they arrive in one UDP datagram: a message, or a bundle of messages and
// bundles. Each message is decoded by liblo (lo_message_deserialise: the type tags, the
// arguments' sizes, alignment and byte order); the bundle frame around them ("#bundle", a time
// tag, then size-prefixed elements) is walked here, because liblo 0.31 walks bundles only in its
// server, which binds every interface, while input here listens on the address given (loopback
// unless told). Pure logic: bytes in, messages out; a datagram that is not OSC is one Failure.
//
//   const Result<std::vector<OscMessage>> m = decode_osc(datagram);
//   if (!m.ok()) ++dropped;  // m.reason(): "bundle element 2: size 40 past the datagram's end"
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace l2 {

// One argument: its OSC type tag and its value, by kind. Other types keep only their tag.
struct OscArg {
  char type = 0;             // 'i', 'h', 'f', 'd', 's', 'S', ...
  std::int64_t integer = 0;  // i, h
  double real = 0;           // f, d
  std::string text;          // s, S

  bool is_int32() const { return type == 'i'; }
  bool is_real() const { return type == 'f' || type == 'd'; }
  bool is_text() const { return type == 's' || type == 'S'; }
};

struct OscMessage {
  std::string address;  // "/tuio/2Dcur"
  std::vector<OscArg> args;
};

// A datagram holds at most this many messages (a TUIO frame of 32 cursors holds 35), and its
// bundles nest at most this deep (a bundle in a bundle: 2): more is refused, not decoded.
inline constexpr int kMaxOscMessages = 256;
inline constexpr int kMaxOscBundleDepth = 4;

// The messages of one datagram, in order (a bundle's time tag is not kept: TUIO sends every
// bundle for now). A datagram that is not a whole OSC packet is a Failure saying why.
Result<std::vector<OscMessage>> decode_osc(std::span<const std::uint8_t> datagram);

}  // namespace l2
