// A session's shared screens on the coordinator (pure apart from the share inbox, fed here
// with JPEGs from libjpeg's encoder): where a share's window goes, the slots' ids and refusals,
// and the DESKTOP lines each pipeserver is sent for a share's window as frames go by.
#include "desktops/session_shares.hpp"

#include <gtest/gtest.h>

#include "balance/desktop_messages.hpp"
#include "control_page/share_inbox.hpp"
#include "test_jpeg.hpp"

namespace l2 {
namespace {

TEST(SharePlace, HalfTheCanvasAtMostKeepingTheAspect) {
  // 1280x720 on a 1920x1080 canvas: at most 960x540, centred.
  EXPECT_EQ(share_place(1920, 1080, 1280, 720, -1, -1), (Rect{480, 270, 960, 540}));
  // Dropped at 300,200; a small share keeps its size.
  EXPECT_EQ(share_place(1920, 1080, 200, 100, 300, 200), (Rect{200, 150, 200, 100}));
  // A tall share on a wide canvas: bound by the height.
  EXPECT_EQ(share_place(4000, 1000, 1000, 2000, -1, -1), (Rect{1875, 250, 250, 500}));
}

// Two pipeservers, each with one tile: the canvas's left and right halves of 400x200.
TileLayout two_halves_layout() {
  TileLayout layout;
  for (int p = 0; p < 2; ++p) {
    PipeserverPlan plan;
    plan.pipeserver = p;
    PackedTile t;
    t.tile.on_canvas = {p * 200, 0, 200, 200};
    plan.tiles.push_back(t);
    layout.pipeservers.push_back(plan);
  }
  return layout;
}

Session session_of(int shares) {
  Session s;
  SessionWindow w;
  w.id = 4;
  w.source = "picture";
  w.on_canvas = {0, 0, 10, 10};
  s.windows.push_back(w);
  s.shares = shares;
  return s;
}

TEST(SessionShares, SlotsAfterTheFilesWindowsAndRefusalsWhenFull) {
  SessionShares none(session_of(0), two_halves_layout());
  EXPECT_EQ(none.free_window().reason(),
            "the session takes no shares (give it shares = N, docs/session-file.md)");
  SessionShares shares(session_of(2), two_halves_layout());
  auto inbox = std::make_shared<ShareInbox>();
  ASSERT_EQ(*shares.free_window(), 5);
  shares.open(5, share_source(inbox, 5, 64, 32), "alice", 3);
  ASSERT_EQ(*shares.free_window(), 6);
  shares.open(6, share_source(inbox, 6, 64, 32), "bob", 3);
  EXPECT_EQ(shares.free_window().reason(),
            "all 2 share windows are in use (the session's shares = 2)");
  EXPECT_TRUE(shares.close(5));
  EXPECT_FALSE(shares.close(5));
  EXPECT_EQ(*shares.free_window(), 5);
  EXPECT_EQ(shares.summary(),
            "shares: window 5 shared by alice (64x32) from frame 3\n"
            "shares: window 6 shared by bob (64x32) from frame 3\n");
}

TEST(SessionShares, EachPipeserverIsSentWhatItsTileShowsOfTheShare) {
  SessionShares shares(session_of(1), two_halves_layout());
  auto inbox = std::make_shared<ShareInbox>();
  // Frame 0: the slot is free, its 1x1 desktop sampled by no window.
  EXPECT_EQ(shares.answer(0, 0, {}), (std::vector<std::string>{"DESKTOP 0 1 1 0 0"}));
  shares.open(5, share_source(inbox, 5, 64, 32), "alice", 1);
  inbox->open(5, "alice", 64, 32);
  ASSERT_EQ(inbox->admit(5).status, 200);
  ASSERT_EQ(inbox->put(5, test::two_halves(64, 32)).status, 200);
  shares.take_updates();
  // Pipeserver 1 had not asked for frame 0 yet: that frame stays the free slot's.
  EXPECT_EQ(shares.answer(1, 0, {}), (std::vector<std::string>{"DESKTOP 0 1 1 0 0"}));
  // From frame 1 the window is shown across both halves at 150,50 (100x50, the share 64x32
  // fitted: 78x39 of it... the parts each tile samples are sent whole.
  const std::vector<WindowPlace> shown{{4, {0, 0, 10, 10}}, {5, {150, 50, 100, 50}}};
  const std::vector<std::string> left = shares.answer(0, 1, shown);
  const std::vector<std::string> right = shares.answer(1, 1, shown);
  ASSERT_GE(left.size(), 2u);
  ASSERT_GE(right.size(), 2u);
  const DesktopMessage l = decode_desktop(left[0]), r = decode_desktop(right[0]);
  EXPECT_EQ(l.width, 64);
  EXPECT_EQ(l.height, 32);
  ASSERT_EQ(l.regions.size(), 1u);
  ASSERT_EQ(r.regions.size(), 1u);
  // The left tile shows the window's left half (canvas 150..200 of 150..250): the share's left
  // columns, red; the right tile its right columns, blue.
  EXPECT_EQ(l.regions[0].x, 0);
  EXPECT_EQ(r.regions[0].right(), 64);
  const DesktopRect lp = decode_desktop_rect(left[1]), rp = decode_desktop_rect(right[1]);
  EXPECT_NEAR(lp.rgb[0], 255, 12);
  EXPECT_NEAR(rp.rgb[rp.rgb.size() - 1], 255, 12);  // the last pixel's blue
  // Nothing new shared: frame 2 sends no pixels again.
  EXPECT_EQ(decode_desktop(shares.answer(0, 2, shown)[0]).rects, 0);
}

}  // namespace
}  // namespace l2
