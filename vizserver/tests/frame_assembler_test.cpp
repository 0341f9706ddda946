#include "vizserver/frame_assembler.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace l2::viz {
namespace {

using ::testing::HasSubstr;

ReceivedTile solid(std::uint32_t frame, int display, int x, int y, int w, int h, Rgb c) {
  ReceivedTile t{TileHeader{frame, static_cast<std::uint32_t>(display), x, y,
                            static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h)},
                 {}};
  for (int i = 0; i < w * h; ++i) t.pixels.insert(t.pixels.end(), {c.r, c.g, c.b});
  return t;
}

constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255};

class Assembler : public ::testing::Test {
 protected:
  FrameAssembler a{{{8, 4}, {4, 4}}, 2};
  void SetUp() override {
    ASSERT_TRUE(a.connect(0).ok());
    ASSERT_TRUE(a.connect(1).ok());
  }
};

TEST_F(Assembler, HigherPipeserverWinsWhateverTheArrivalOrder) {
  // Pipeserver 1's tile arrives first and is finished first; 0's arrives later over it.
  ASSERT_TRUE(a.add_tile(1, solid(0, 0, 2, 0, 4, 2, kRed)).ok());
  ASSERT_TRUE(a.finish(1, FrameDone{1, 0, 1}).ok());
  EXPECT_TRUE(a.take_complete().empty());  // 0 has not finished
  ASSERT_TRUE(a.add_tile(0, solid(0, 0, 0, 0, 4, 4, kGreen)).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 1}).ok());
  const auto frames = a.take_complete();
  ASSERT_EQ(frames.size(), 1u);
  const RgbImage& d = frames[0].displays[0];
  EXPECT_EQ(d.at(1, 1), kGreen);  // only 0 covers it
  EXPECT_EQ(d.at(2, 0), kRed);    // overlap: 1 wins
  EXPECT_EQ(d.at(3, 1), kRed);
  EXPECT_EQ(d.at(3, 2), kGreen);  // below 1's tile
  EXPECT_EQ(d.at(5, 1), kRed);
  EXPECT_EQ(d.at(6, 0), (Rgb{}));  // nobody: black background
  EXPECT_EQ(frames[0].tiles, 2u);
  EXPECT_EQ(frames[0].displays[1], RgbImage(4, 4));
}

TEST_F(Assembler, WithinOnePipeserverTheLaterTileWins) {
  ASSERT_TRUE(a.add_tile(0, solid(0, 1, 0, 0, 2, 2, kRed)).ok());
  ASSERT_TRUE(a.add_tile(0, solid(0, 1, 1, 1, 2, 2, kBlue)).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 2}).ok());
  ASSERT_TRUE(a.finish(1, FrameDone{1, 0, 0}).ok());
  const auto frames = a.take_complete();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].displays[1].at(0, 0), kRed);
  EXPECT_EQ(frames[0].displays[1].at(1, 1), kBlue);
  EXPECT_EQ(frames[0].displays[1].at(2, 2), kBlue);
}

TEST_F(Assembler, ClipsAndMissingDisplaysAreCountedPerFrame) {
  ASSERT_TRUE(a.add_tile(0, solid(3, 1, 2, 3, 4, 2, kRed)).ok());  // 2 of 4 columns, 1 of 2 rows
  ASSERT_TRUE(a.add_tile(0, solid(3, 9, 0, 0, 1, 5, kRed)).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 3, 2}).ok());
  ASSERT_TRUE(a.finish(1, FrameDone{1, 3, 0}).ok());
  const auto frames = a.take_complete();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].frame, 3u);
  EXPECT_EQ(frames[0].counts.clips, 2u);
  EXPECT_EQ(frames[0].counts.missing_display, 5u);
  EXPECT_EQ(frames[0].displays[1].at(3, 3), kRed);
  EXPECT_EQ(a.buffered_bytes(), 0u);
}

TEST_F(Assembler, FramesCompleteInOrderAndASkippedNumberMeansNoTiles) {
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 0}).ok());
  ASSERT_TRUE(a.add_tile(0, solid(1, 0, 0, 0, 1, 1, kRed)).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 1, 1}).ok());
  ASSERT_TRUE(a.finish(1, FrameDone{1, 1, 0}).ok());  // 1 skipped frame 0
  const auto frames = a.take_complete();
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].frame, 0u);
  EXPECT_EQ(frames[1].frame, 1u);
  EXPECT_EQ(frames[1].displays[0].at(0, 0), kRed);
  EXPECT_EQ(a.last_composed(), 1u);
}

TEST_F(Assembler, ProtocolViolationsAreNamed) {
  EXPECT_THAT(a.finish(0, FrameDone{0, 0, 2}).reason(),
              HasSubstr("pipeserver 0: FRAME_DONE for frame 0 announces 2 tiles, 0 arrived"));
  ASSERT_TRUE(a.finish(0, FrameDone{0, 5, 0}).ok());
  EXPECT_THAT(a.add_tile(0, solid(4, 0, 0, 0, 1, 1, kRed)).reason(),
              HasSubstr("pipeserver 0: TILE for frame 4 after its FRAME_DONE for frame 5"));
  ASSERT_TRUE(a.add_tile(1, solid(6, 0, 0, 0, 1, 1, kRed)).ok());
  EXPECT_THAT(a.add_tile(1, solid(7, 0, 0, 0, 1, 1, kRed)).reason(),
              HasSubstr("pipeserver 1: TILE for frame 7 while frame 6 has no FRAME_DONE"));
  EXPECT_THAT(a.finish(1, FrameDone{0, 6, 1}).reason(),
              HasSubstr("pipeserver 1: FRAME_DONE names pipeserver 0"));
  EXPECT_THAT(a.connect(1).reason(), HasSubstr("pipeserver 1 is already connected"));
  EXPECT_THAT(a.connect(2).reason(), HasSubstr("outside 0..1"));
}

TEST_F(Assembler, DisconnectDuringAFrameNamesServerAndFrame) {
  ASSERT_TRUE(a.add_tile(1, solid(2, 0, 0, 0, 1, 1, kRed)).ok());
  EXPECT_EQ(a.frame_waiting_for(0), 2u);
  EXPECT_EQ(a.disconnect(1).reason(),
            "pipeserver 1 disconnected during frame 2 (1 tiles received, no FRAME_DONE)");
}

TEST_F(Assembler, DisconnectBetweenFramesFailsOnlyWhenAFrameNeedsIt) {
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 0}).ok());
  ASSERT_TRUE(a.finish(1, FrameDone{1, 0, 0}).ok());
  EXPECT_EQ(a.take_complete().size(), 1u);
  EXPECT_TRUE(a.disconnect(1).ok());
  EXPECT_THAT(a.add_tile(0, solid(1, 0, 0, 0, 1, 1, kRed)).reason(),
              HasSubstr("frame 1 can never complete: pipeserver 1 disconnected after frame 0"));
  EXPECT_TRUE(a.disconnect(0).ok());
  EXPECT_TRUE(a.all_done());
}

TEST_F(Assembler, DisconnectWhileAnotherFrameWaitsIsAnError) {
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 0}).ok());
  EXPECT_EQ(a.disconnect(1).reason(),
            "pipeserver 1 disconnected before finishing any frame; frame 0 is waiting for it");
}

// Surviving losses (l2wall run --survive-host-loss): a pipeserver closing mid-frame is no error
// and the frame waits for the verdict; once lost, frames complete from the others' tiles, with
// what the lost one sent of its unfinished frame, and later frames never wait for it.
TEST_F(Assembler, ALostPipeserverIsWaitedForByNoFrame) {
  a.survive_losses();
  ASSERT_TRUE(a.add_tile(1, solid(0, 0, 4, 0, 4, 4, kRed)).ok());  // no FRAME_DONE: killed
  EXPECT_TRUE(a.disconnect(1).ok());
  ASSERT_TRUE(a.add_tile(0, solid(0, 0, 0, 0, 4, 4, kGreen)).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 1}).ok());
  EXPECT_TRUE(a.take_complete().empty());  // the verdict is not in yet
  EXPECT_EQ(a.frame_waiting_for(1), 0u);
  ASSERT_TRUE(a.lose(1).ok());
  EXPECT_TRUE(a.lost(1));
  EXPECT_FALSE(a.frame_waiting_for(1).has_value());
  auto frames = a.take_complete();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].displays[0].at(1, 1), kGreen);
  EXPECT_EQ(frames[0].displays[0].at(5, 1), kRed);                  // what it sent before it died
  ASSERT_TRUE(a.add_tile(0, solid(1, 0, 0, 0, 8, 4, kBlue)).ok());  // its tiles now 0's
  ASSERT_TRUE(a.finish(0, FrameDone{0, 1, 1}).ok());
  frames = a.take_complete();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].frame, 1u);
  EXPECT_EQ(frames[0].displays[0].at(5, 1), kBlue);
  EXPECT_THAT(a.connect(1).reason(), HasSubstr("pipeserver 1 is already connected"));
  EXPECT_TRUE(a.disconnect(0).ok());
  EXPECT_TRUE(a.all_done());
  EXPECT_THAT(a.lose(2).reason(), HasSubstr("outside 0..1"));
}

// One lost before it ever connected (killed at frame 0): the other's frames complete alone, and
// it may no longer say HELLO.
TEST(AssemblerLosses, APipeserverLostBeforeConnectingIsNotAwaited) {
  FrameAssembler a{{{4, 4}}, 2};
  a.survive_losses();
  ASSERT_TRUE(a.connect(0).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 0}).ok());
  EXPECT_TRUE(a.take_complete().empty());
  ASSERT_TRUE(a.lose(1).ok());
  EXPECT_EQ(a.take_complete().size(), 1u);
  EXPECT_EQ(a.connect(1).reason(), "pipeserver 1 was lost: the run goes on without it");
  EXPECT_TRUE(a.disconnect(0).ok());
  EXPECT_TRUE(a.all_done());
}

TEST(AssemblerLimits, BufferedBytesAreBounded) {
  FrameAssembler a({{8, 8}}, 2, {}, 100);
  ASSERT_TRUE(a.connect(0).ok());
  ASSERT_TRUE(a.add_tile(0, solid(0, 0, 0, 0, 5, 5, kRed)).ok());  // 75 bytes
  EXPECT_THAT(a.add_tile(0, solid(0, 0, 0, 0, 3, 3, kRed)).reason(),
              HasSubstr("tiles buffered waiting for frame 0"));
}

TEST(AssemblerLimits, BackgroundColourFillsUnwrittenPixels) {
  FrameAssembler a({{2, 2}}, 1, Rgb{1, 2, 3});
  ASSERT_TRUE(a.connect(0).ok());
  ASSERT_TRUE(a.finish(0, FrameDone{0, 0, 0}).ok());
  const auto frames = a.take_complete();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].displays[0], RgbImage(2, 2, Rgb{1, 2, 3}));
}

// Only pixels no COPY tile covers get the background first (compose()): a KEY or DEPTH tile that
// writes nothing must still show it, and so must a display's pixels beside a COPY tile clipped
// at its edge. Several frames, so that the pictures reuse memory earlier frames wrote.
TEST(AssemblerLimits, BackgroundShowsWhereOnlyKeyOrDepthTilesOrNoTilesAre) {
  constexpr Rgb kBackground{1, 2, 3};
  FrameAssembler a({{6, 4}}, 1, kBackground);
  ASSERT_TRUE(a.connect(0).ok());
  for (std::uint32_t f = 0; f < 4; ++f) {
    ASSERT_TRUE(a.add_tile(0, solid(f, 0, -2, -1, 4, 3, kGreen)).ok());  // clipped: 2x2 left
    ReceivedTile key = solid(f, 0, 2, 0, 2, 4, kRed);  // every pixel the key colour
    key.header.how = TileKind::Key;
    key.header.key = 0xFF0000;
    ASSERT_TRUE(a.add_tile(0, std::move(key)).ok());
    ReceivedTile depth = solid(f, 0, 4, 0, 2, 4, kBlue);
    depth.header.how = TileKind::Depth;
    depth.pixels.assign(depth.header.pixel_bytes(), 0xFF);  // far plane: writes nothing
    ASSERT_TRUE(a.add_tile(0, std::move(depth)).ok());
    ASSERT_TRUE(a.finish(0, FrameDone{0, f, 3}).ok());
    const auto frames = a.take_complete();
    ASSERT_EQ(frames.size(), 1u);
    RgbImage expected(6, 4, kBackground);
    expected.fill_rect(0, 0, 2, 2, kGreen);
    EXPECT_EQ(frames[0].displays[0], expected) << "frame " << f;
  }
}

}  // namespace
}  // namespace l2::viz
