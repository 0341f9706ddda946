#include "desktops/live_windows.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

Session three_windows() {
  Session s;
  s.windows = {{0, "picture", "a.png", {0, 0, 100, 80}, 0, "", {}},
               {1, "mesh", "", {50, 40, 200, 100}, 1, "", {}},
               {7, "swap", "", {10, 10, 20, 20}, 2, "", {}}};
  return s;
}

TEST(LiveWindows, CommandsShowFromTheNextFrameDecidedInTheOrderTaken) {
  LiveWindows w(three_windows());
  EXPECT_EQ(w.command("  move 1 -5 6   70 8 ").why, "");
  EXPECT_EQ(w.command("raise 0").why, "");
  EXPECT_EQ(w.command("close 7").why, "");
  // Not decided yet: every frame shows the session file's windows.
  EXPECT_EQ(w.shown_at(3),
            (std::vector<WindowPlace>{
                {0, {0, 0, 100, 80}}, {1, {50, 40, 200, 100}}, {7, {10, 10, 20, 20}}}));
  EXPECT_EQ(w.line_for(1), "WINDOWS 1 2 1 -5 6 70 8 0 0 0 100 80");
  EXPECT_EQ(w.command("move 0 1 2 3 4").why, "");
  EXPECT_EQ(w.line_for(2), "WINDOWS 2 2 1 -5 6 70 8 0 1 2 3 4");
  EXPECT_EQ(w.shown_at(9), (std::vector<WindowPlace>{{1, {-5, 6, 70, 8}}, {0, {1, 2, 3, 4}}}));
  EXPECT_EQ(w.summary(),
            "windows: move 1 -5 6 70 8 from frame 1\nwindows: raise 0 from frame 1\n"
            "windows: close 7 from frame 1\nwindows: move 0 1 2 3 4 from frame 2\n");
}

TEST(LiveWindows, RefusesWhatIsNotACommandInOneLineAndChangesNothing) {
  LiveWindows w(three_windows());
  EXPECT_EQ(w.command("jump 1").why, "expected 'move ID X Y W H', 'raise ID' or 'close ID'");
  EXPECT_EQ(w.command("").why, "expected 'move ID X Y W H', 'raise ID' or 'close ID'");
  EXPECT_EQ(w.command("move 1 2 3 0 5").why,
            "command 'move 1 2 3 0 5': W must be an integer 1..16384, got '0'");
  EXPECT_EQ(w.command("move 1 2 3 4").why,
            "command 'move 1 2 3 4': H must be an integer 1..16384, got ''");
  EXPECT_EQ(w.command("raise x").why, "command 'raise x': ID must be an integer 0..9999, got 'x'");
  EXPECT_EQ(w.command("raise 1 2").why, "command 'raise 1 2': more words than its count says");
  EXPECT_EQ(w.command("raise 4").why, "window 4 is not in the session");
  EXPECT_TRUE(w.command("raise 4").no_such_window);  // the control page answers 404
  EXPECT_FALSE(w.command("raise x").no_such_window);
  EXPECT_EQ(w.command("close 7").why, "");
  EXPECT_EQ(w.command("raise 7").why, "window 7 is closed");
  EXPECT_EQ(w.windows(), "WINDOWS 0 3 0 0 0 100 80 1 50 40 200 100 7 10 10 20 20\n");
}

}  // namespace
}  // namespace l2
