#include "balance/control_messages.hpp"

#include <gtest/gtest.h>

#include "test_walls.hpp"

#include "balance/balancer.hpp"

namespace l2 {
namespace {

using test::strips_wall;

TEST(ControlMessages, TimesRoundTrip) {
  const std::string line = encode(TimesMessage{7, 2, {0.0125, 0.5, 0}, {}});
  EXPECT_EQ(line, "TIMES 7 2 3 0.0125 0.5 0");
  const TimesMessage m = decode_times(line);
  EXPECT_EQ(m.frame, 7);
  EXPECT_EQ(m.pipeserver, 2);
  EXPECT_EQ(m.seconds, (std::vector<double>{0.0125, 0.5, 0}));
}

TEST(ControlMessages, TimesCarryTheBatchesFootprints) {
  TimesMessage sent{3, 1, {0.25}, {{{10, 20, 30, 40}, 640}, {{0, 0, 1, 1}, 2.4}}};
  const std::string line = encode(sent);
  EXPECT_EQ(line, "TIMES 3 1 1 0.25 BATCHES 2 10 20 30 40 640 0 0 1 1 2");
  const TimesMessage m = decode_times(line);
  EXPECT_EQ(m.seconds, (std::vector<double>{0.25}));
  EXPECT_EQ(m.footprints, (Footprints{{{10, 20, 30, 40}, 640}, {{0, 0, 1, 1}, 2}}));
}

TEST(ControlMessages, WindowsRoundTrip) {
  EXPECT_EQ(encode(WantMessage{9, 3}), "WANT 9 3");
  EXPECT_EQ(decode_want("WANT 9 3").pipeserver, 3);
  const WindowsMessage m{4, {{2, {-10, 20, 300, 200}}, {0, {5, 6, 7, 8}}}};
  EXPECT_EQ(encode(m), "WINDOWS 4 2 2 -10 20 300 200 0 5 6 7 8");
  const WindowsMessage d = decode_windows(encode(m));
  EXPECT_EQ(d.frame, 4);
  EXPECT_EQ(d.windows, m.windows);
  EXPECT_TRUE(decode_windows("WINDOWS 5 0").windows.empty());  // every window closed
  EXPECT_THROW(decode_windows("WINDOWS 4 2 1 0 0 5 5 1 0 0 5 5"), ControlError);  // id twice
  EXPECT_THROW(decode_windows("WINDOWS 4 1 1 0 0 0 5"), ControlError);            // no width
  EXPECT_THROW(decode_windows("WINDOWS 4 33"), ControlError);                     // too many
  EXPECT_THROW(decode_windows("WINDOWS 4 1 1 0 0 5 5 9"), ControlError);          // a word more
}

TEST(ControlMessages, LayoutRoundTrip) {
  const LayoutMessage m{3, {{0, 0, 33, 38}, {33, 0, 67, 38}}, {1, 0}, {}};
  EXPECT_EQ(encode(m), "LAYOUT 3 2 0 0 33 38 1 33 0 67 38 0");
  const LayoutMessage d = decode_layout(encode(m));
  EXPECT_EQ(d.frame, 3);
  EXPECT_EQ(d.tiles, m.tiles);
  EXPECT_EQ(d.pipeservers, m.pipeservers);
}

// A layout without a dead host names it, and every pipeserver plans it without that one.
TEST(ControlMessages, LayoutNamesTheGonePipeservers) {
  const LayoutMessage m{4, {{0, 0, 50, 100}, {50, 0, 50, 100}}, {0, 0}, {1}};
  EXPECT_EQ(encode(m), "LAYOUT 4 2 0 0 50 100 0 50 0 50 100 0 GONE 1 1");
  const LayoutMessage d = decode_layout(encode(m));
  EXPECT_EQ(d.pipeservers, m.pipeservers);
  EXPECT_EQ(d.gone, std::vector<int>{1});
  const TileLayout heard = plan_from_message(strips_wall(), d);
  ASSERT_EQ(heard.pipeservers.size(), 2u);
  EXPECT_EQ(heard.pipeservers[0].tiles.size(), 2u);
  EXPECT_TRUE(heard.pipeservers[1].tiles.empty());
  // And back: the coordinator's message of that plan says the same.
  EXPECT_EQ(encode(layout_message(4, heard)), encode(m));
  // Without GONE the planner still wants a tile for every pipeserver.
  EXPECT_THROW(plan_from_message(strips_wall(), LayoutMessage{4, m.tiles, m.pipeservers, {}}),
               LayoutError);
}

void expect_error(std::string_view line, bool layout, const std::string& what) {
  try {
    if (layout)
      decode_layout(line);
    else
      decode_times(line);
    ADD_FAILURE() << "accepted: " << line;
  } catch (const ControlError& e) {
    EXPECT_EQ(e.what(), what);
  }
}

TEST(ControlMessages, BadLinesAreOneLineErrors) {
  expect_error("READY 1", false, "control line 'READY 1': not a TIMES message");
  expect_error("TIMES 1 300 0", false,
               "control line 'TIMES 1 300 0': pipeserver must be an integer 0..255, got '300'");
  expect_error("TIMES 1 0 2 0.5", false,
               "control line 'TIMES 1 0 2 0.5': a render time must be seconds >= 0, got ''");
  expect_error("TIMES 1 0 1 -1", false,
               "control line 'TIMES 1 0 1 -1': a render time must be seconds >= 0, got '-1'");
  expect_error("TIMES 1 0 1 0.5 BATCHES 1 0 0 0 5 9", false,
               "control line 'TIMES 1 0 1 0.5 BATCHES 1 0 0 0 5 9': batch width must be an "
               "integer 1..65535, got '0'");
  expect_error("TIMES 1 0 0 BATCHES 99999999 1", false,
               "control line 'TIMES 1 0 0 BATCHES 99999999 1': batch count must be an integer "
               "1..65536, got '99999999'");
  expect_error("TIMES 1 0 1 0.5 9", false,
               "control line 'TIMES 1 0 1 0.5 9': more words than its count says");
  expect_error("TIMES 1 0 99999999999", false,
               "control line 'TIMES 1 0 99999999999': tile count must be an integer 0..65536, "
               "got '99999999999'");
  expect_error("LAYOUT 0 1 0 0 0 10 0", true,
               "control line 'LAYOUT 0 1 0 0 0 10 0': width must be an integer 1..65535, got '0'");
  expect_error("LAYOUT 0 1 0 0 5 10 0 GONE 2 1", true,
               "control line 'LAYOUT 0 1 0 0 5 10 0 GONE 2 1': gone pipeserver must be an integer "
               "0..255, got ''");
  expect_error(
      "LAYOUT 0 1 0 0 5 10 0 GONE 2 3 1", true,
      "control line 'LAYOUT 0 1 0 0 5 10 0 GONE 2 3 1': gone pipeservers must be ascending");
  expect_error("LAYOUT 0 1 0 0 5 10 0 GONE 0", true,
               "control line 'LAYOUT 0 1 0 0 5 10 0 GONE 0': gone count must be an integer "
               "1..256, got '0'");
  expect_error(std::string("LAYOUT \x1b[2J") + std::string(60, '9'), true,
               "control line 'LAYOUT ?[2J" + std::string(29, '9') +
                   "...': frame must be an "
                   "integer 0..1073741824, got '?[2J" +
                   std::string(36, '9') + "...'");
}

TEST(ControlMessages, APipeserverPlansWhatTheCoordinatorPlanned) {
  BalanceSettings s;
  s.mode = BalanceMode::Strips;
  s.assign = true;
  s.motion = {1.0, 0};
  Balancer b(strips_wall(), s);
  b.next({{7.5, 2.5}, {2.5, 2.5}});
  const TileLayout& planned = b.layout();
  const TileLayout heard =
      plan_from_message(strips_wall(), decode_layout(encode(layout_message(1, planned))));
  EXPECT_EQ(heard.logical_tiles, planned.logical_tiles);
  EXPECT_EQ(heard.tile_pipeserver, planned.tile_pipeserver);
  ASSERT_EQ(heard.pipeservers.size(), planned.pipeservers.size());
  for (std::size_t i = 0; i < heard.pipeservers.size(); ++i) {
    ASSERT_EQ(heard.pipeservers[i].tiles.size(), planned.pipeservers[i].tiles.size());
    for (std::size_t t = 0; t < heard.pipeservers[i].tiles.size(); ++t) {
      EXPECT_EQ(heard.pipeservers[i].tiles[t].fb_x, planned.pipeservers[i].tiles[t].fb_x);
      EXPECT_EQ(heard.pipeservers[i].tiles[t].fb_y, planned.pipeservers[i].tiles[t].fb_y);
      EXPECT_EQ(heard.pipeservers[i].tiles[t].tile.on_canvas,
                planned.pipeservers[i].tiles[t].tile.on_canvas);
    }
  }
}

}  // namespace
}  // namespace l2
