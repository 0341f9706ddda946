// OSC datagrams to messages: what liblo encodes comes back as written, and every way a datagram
// can fail to be OSC is one Failure saying where.
#include "touch/osc_packet.hpp"

#include <gtest/gtest.h>

#include "tuio_datagrams.hpp"

namespace l2 {
namespace {

using namespace testing_support;

std::vector<std::uint8_t> bytes(std::initializer_list<int> values) {
  std::vector<std::uint8_t> out;
  for (const int v : values) out.push_back(static_cast<std::uint8_t>(v));
  return out;
}

void append(std::vector<std::uint8_t>& to, const std::string& padded) {
  to.insert(to.end(), padded.begin(), padded.end());
}

void append_u32(std::vector<std::uint8_t>& to, std::uint32_t v) {
  for (const int shift : {24, 16, 8, 0}) to.push_back(static_cast<std::uint8_t>(v >> shift));
}

std::vector<std::uint8_t> bundle_of(const std::vector<std::vector<std::uint8_t>>& elements) {
  std::vector<std::uint8_t> b;
  append(b, std::string("#bundle\0", 8));
  append_u32(b, 0);
  append_u32(b, 1);  // the time tag "now"
  for (const auto& e : elements) {
    append_u32(b, static_cast<std::uint32_t>(e.size()));
    b.insert(b.end(), e.begin(), e.end());
  }
  return b;
}

// "/a" with one int32 argument, 7.
std::vector<std::uint8_t> small_message() {
  std::vector<std::uint8_t> m;
  append(m, std::string("/a\0\0,i\0\0", 8));
  append_u32(m, 7);
  return m;
}

TEST(OscPacket, ATuioBundleComesBackAsLibloEncodedIt) {
  const auto m = decode_osc(tuio_frame(12, {{3, 0.25f, 0.75f}}));
  ASSERT_TRUE(m.ok()) << m.reason();
  ASSERT_EQ(m->size(), 4u);
  for (const OscMessage& each : *m) EXPECT_EQ(each.address, "/tuio/2Dcur");
  EXPECT_EQ((*m)[0].args[0].text, "source");
  EXPECT_EQ((*m)[0].args[1].text, "test@127.0.0.1");
  ASSERT_EQ((*m)[1].args.size(), 2u);
  EXPECT_EQ((*m)[1].args[0].text, "alive");
  EXPECT_EQ((*m)[1].args[1].type, 'i');
  EXPECT_EQ((*m)[1].args[1].integer, 3);
  const OscMessage& set = (*m)[2];
  ASSERT_EQ(set.args.size(), 7u);
  EXPECT_EQ(set.args[0].text, "set");
  EXPECT_EQ(set.args[1].integer, 3);
  EXPECT_EQ(set.args[2].type, 'f');
  EXPECT_EQ(set.args[2].real, 0.25);
  EXPECT_EQ(set.args[3].real, 0.75);
  EXPECT_EQ((*m)[3].args[1].integer, 12);
}

TEST(OscPacket, AMessageAloneAndNestedBundles) {
  const auto alone = decode_osc(small_message());
  ASSERT_TRUE(alone.ok()) << alone.reason();
  ASSERT_EQ(alone->size(), 1u);
  EXPECT_EQ((*alone)[0].address, "/a");
  EXPECT_EQ((*alone)[0].args[0].integer, 7);
  const auto nested = decode_osc(bundle_of({small_message(), bundle_of({small_message()})}));
  ASSERT_TRUE(nested.ok()) << nested.reason();
  EXPECT_EQ(nested->size(), 2u);
}

TEST(OscPacket, WhatIsNotOscIsOneFailureSayingWhere) {
  EXPECT_EQ(decode_osc({}).reason(), "0 bytes: not a multiple of 4");
  EXPECT_EQ(decode_osc(bytes({'/', 'a', 0})).reason(), "3 bytes: not a multiple of 4");
  EXPECT_EQ(decode_osc(bytes({'/', 'a', 'b', 'c'})).reason(),
            "not an OSC message: its address is not a terminated string");
  std::vector<std::uint8_t> past = bundle_of({small_message()});
  past[19] = 40;  // the element's size, beyond the datagram
  EXPECT_EQ(decode_osc(past).reason(),
            "bundle element 0: size 40 past the datagram's end or not a multiple of 4");
  std::vector<std::uint8_t> odd = bundle_of({small_message()});
  odd[19] = 6;
  EXPECT_EQ(decode_osc(odd).reason(),
            "bundle element 0: size 6 past the datagram's end or not a multiple of 4");
  std::vector<std::uint8_t> no_size = bundle_of({small_message()});
  append(no_size, std::string("\0\0\0\0", 4));
  EXPECT_EQ(decode_osc(no_size).reason(),
            "bundle element 1: size 0 past the datagram's end or not a multiple of 4");
  std::vector<std::uint8_t> bad_inside = small_message();
  bad_inside[5] = 'i';
  bad_inside[6] = 'i';  // ",ii": a second int32 the message does not hold
  EXPECT_EQ(decode_osc(bundle_of({small_message(), bad_inside})).reason(),
            "bundle element 1: not an OSC message: an argument its bytes do not hold");
  EXPECT_EQ(decode_osc(bytes({'#', 'b', 'u', 'n', 'd', 'l', 'e', 0})).reason(),
            "a bundle shorter than its header");
}

TEST(OscPacket, BundlesTooDeepOrTooManyMessagesAreRefused) {
  std::vector<std::uint8_t> deep = small_message();
  for (int k = 0; k <= kMaxOscBundleDepth; ++k) deep = bundle_of({deep});
  EXPECT_EQ(decode_osc(deep).reason(),
            "bundle element 0: bundle element 0: bundle element 0: bundle element 0: bundles "
            "nested deeper than 4");
  const std::vector<std::vector<std::uint8_t>> many(kMaxOscMessages + 1, small_message());
  EXPECT_EQ(decode_osc(bundle_of(many)).reason(), "bundle element 256: more than 256 messages");
  const std::vector<std::vector<std::uint8_t>> most(kMaxOscMessages, small_message());
  EXPECT_TRUE(decode_osc(bundle_of(most)).ok());
}

}  // namespace
}  // namespace l2
