// Frames over a network as changes (frame_delta.hpp): what arrives is the frame sent, byte for
// byte, for every codec; unchanged rows cost nothing; hostile messages are refused, not applied.
#include "dvi_link/frame_delta.hpp"

#include <gtest/gtest.h>

#include <random>

namespace l2 {
namespace {

constexpr int kW = 64, kH = 20;
constexpr std::size_t kBytes = std::size_t{kW} * kH * 3;
constexpr std::size_t kHeader = 24 + (kH + 7) / 8;  // header and bitmap, no rows

std::vector<std::uint8_t> noise(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> f(kBytes);
  for (auto& b : f) b = static_cast<std::uint8_t>(rng());
  return f;
}

// A horizontal ramp: spatially smooth, so its residual is a repeating small step.
std::vector<std::uint8_t> ramp(int shift) {
  std::vector<std::uint8_t> f(kBytes);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW * 3; ++x)
      f[static_cast<std::size_t>(y * kW * 3 + x)] = static_cast<std::uint8_t>(x / 3 + y + shift);
  return f;
}

class EveryCodec : public ::testing::TestWithParam<LinkCodec> {};

TEST_P(EveryCodec, EachFrameArrivesByteForByte) {
  FrameDeltaEncoder encoder(kW, kH, GetParam());
  FrameDeltaDecoder decoder(kW, kH);
  const std::vector<std::vector<std::uint8_t>> frames = {
      noise(1), noise(1), ramp(0), ramp(5), noise(2), std::vector<std::uint8_t>(kBytes)};
  for (const auto& f : frames) {
    const auto m = encoder.encode(f);
    ASSERT_TRUE(decoder.decode(m).ok());
    ASSERT_TRUE(std::equal(f.begin(), f.end(), decoder.frame().begin()));
  }
}

TEST_P(EveryCodec, AnUnchangedFrameIsItsHeaderAlone) {
  if (GetParam() == LinkCodec::Whole) GTEST_SKIP() << "whole frames are sent whole";
  FrameDeltaEncoder encoder(kW, kH, GetParam());
  const auto f = noise(3);
  (void)encoder.encode(f);
  EXPECT_EQ(encoder.encode(f).size(), kHeader);
}

TEST_P(EveryCodec, BlankRectsArriveBlack) {
  FrameDeltaEncoder encoder(kW, kH, GetParam());
  FrameDeltaDecoder decoder(kW, kH);
  const auto f = noise(4);
  const std::vector<BlankRect> blank = {{10, 2, 5, 3}, {60, 19, 10, 4}};
  ASSERT_TRUE(decoder.decode(encoder.encode(f, blank)).ok());
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool black = (x >= 10 && x < 15 && y >= 2 && y < 5) || (x >= 60 && y == 19);
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = static_cast<std::size_t>((y * kW + x) * 3 + c);
        ASSERT_EQ(decoder.frame()[i], black ? 0 : f[i]) << x << "," << y;
      }
    }
}

INSTANTIATE_TEST_SUITE_P(FrameDelta, EveryCodec,
                         ::testing::Values(LinkCodec::Raw, LinkCodec::Lz4, LinkCodec::Zstd,
                                           LinkCodec::Whole),
                         [](const auto& p) { return std::string(link_codec_name(p.param)); });

TEST(FrameDelta, OnlyChangedRowsAreSentAndAFlippedHeaderIsAFewBytes) {
  FrameDeltaEncoder encoder(kW, kH, LinkCodec::Raw);
  auto f = noise(5);
  (void)encoder.encode(f);
  f[7 * kW * 3 + 4] ^= 1;  // one byte of row 7, as a header's parity bit
  f[12 * kW * 3] ^= 0x80;  // one of row 12
  // Stored, not compressed: two rows, each its mode byte and residual.
  EXPECT_EQ(encoder.encode(f).size(), kHeader + 2 * (1 + kW * 3));
  FrameDeltaEncoder packed(kW, kH, LinkCodec::Zstd);
  (void)packed.encode(noise(5));
  EXPECT_LT(packed.encode(f).size(), kHeader + 40);
}

TEST(FrameDelta, SmoothShadingCompressesThroughTheSpatialPrediction) {
  FrameDeltaEncoder encoder(kW, kH, LinkCodec::Lz4);
  // The first frame from black: every row changed; the ramp's residual is 1, 0, 0, 1, ...
  EXPECT_LT(encoder.encode(ramp(0)).size(), kBytes / 10);
}

TEST(FrameDelta, ParsesItsCodecNames) {
  EXPECT_EQ(parse_link_codec("zstd").value(), LinkCodec::Zstd);
  EXPECT_EQ(parse_link_codec("lz4").value(), LinkCodec::Lz4);
  EXPECT_EQ(parse_link_codec("raw").value(), LinkCodec::Raw);
  EXPECT_EQ(parse_link_codec("whole").value(), LinkCodec::Whole);
  EXPECT_EQ(parse_link_codec("gzip").reason(),
            "'gzip' is not a link codec: raw, lz4, zstd or whole");
}

TEST(FrameDelta, AWholeFrameIsItsRowsAndMustSayAllOfThem) {
  FrameDeltaEncoder encoder(kW, kH, LinkCodec::Whole);
  FrameDeltaDecoder decoder(kW, kH);
  const auto f = noise(8);
  const auto span = encoder.encode(f);
  EXPECT_EQ(span.size(), kHeader + kBytes);
  std::vector<std::uint8_t> m(span.begin(), span.end());
  m[16] = 19;  // 19 rows said, 20 marked
  EXPECT_EQ(decoder.decode(m).reason(), "20 rows marked changed, its header says 19");
  m[16] = 20;
  m[24] = 0xFE;  // row 0 unmarked
  m[16] = 19;
  EXPECT_EQ(decoder.decode(m).reason(),
            "a whole frame of 19 rows in 3840 bytes, expected 20 in 3840");
}

// A message altered in transit or by a hostile peer: refused with the reason, frame unchanged.
TEST(FrameDelta, MalformedMessagesAreRefusedAndChangeNothing) {
  FrameDeltaEncoder encoder(kW, kH, LinkCodec::Zstd);
  FrameDeltaDecoder decoder(kW, kH);
  const auto first = noise(6);
  ASSERT_TRUE(decoder.decode(encoder.encode(first)).ok());
  const auto span = encoder.encode(noise(7));
  const std::vector<std::uint8_t> good(span.begin(), span.end());
  const auto refused = [&](std::vector<std::uint8_t> m, const std::string& why) {
    const Status s = decoder.decode(m);
    EXPECT_EQ(s.reason(), why);
    EXPECT_TRUE(std::equal(first.begin(), first.end(), decoder.frame().begin()));
  };
  refused({good.begin(), good.begin() + 10},
          "a frame message of 10 bytes is shorter than its header (27)");
  auto m = good;
  m[0] = 'X';
  refused(m, "not a frame message (magic or version)");
  m = good;
  m[5] = 9;
  refused(m, "unknown codec 9");
  m = good;
  m[8] = 65;
  refused(m, "a 65x20 frame, expected 64x20");
  m = good;
  m.push_back(0);
  refused(m, fmt::format("{} bytes, its header says {}", good.size() + 1, good.size()));
  m = good;
  m[16] = 3;  // changed rows
  refused(m, "20 rows marked changed, its header says 3");
  m = good;
  m[24 + 2] = 0xF0;  // rows 20..23 of a 20-row frame
  refused(m, "rows marked below the frame");
  m = good;
  std::fill(m.begin() + static_cast<std::ptrdiff_t>(kHeader), m.end(), 0xFF);  // the block
  refused(m, "changed row 0 has mode 255");  // noise does not compress: stored as it is
  const auto ramp_span = encoder.encode(ramp(1));
  m.assign(ramp_span.begin(), ramp_span.end());
  ASSERT_EQ(m[5], static_cast<std::uint8_t>(LinkCodec::Zstd));
  std::fill(m.begin() + static_cast<std::ptrdiff_t>(kHeader), m.end(), 0xFF);
  refused(m, "the zstd block does not give the 3860 bytes of 20 changed rows");
}

}  // namespace
}  // namespace l2
