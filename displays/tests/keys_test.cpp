// Keys on the wall window, typed through the X server's own input path (XTEST), as a user's
// keyboard would: space pauses, s asks for a screenshot, q and Esc quit.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "displays/monitor_wall.hpp"
#include "displays/wall_window.hpp"
#include "displays/x_client.hpp"
#include "screen_fixture.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using testing::distinct_picture;
using testing::grid_wall;

// The first action the presenter reports within 2 s (None when there was none).
UserAction next_action(WallPresenter& shown) {
  const auto deadline = std::chrono::steady_clock::now() + 2s;
  while (std::chrono::steady_clock::now() < deadline) {
    if (const UserAction a = shown.poll_events(); a != UserAction::None) return a;
    std::this_thread::sleep_for(5ms);
  }
  return UserAction::None;
}

TEST(Keys, SpaceSAndQAndEscapeOnTheWallWindow) {
  L2_START_XVFB(xvfb, 800, 600);
  const Wall wall = grid_wall(2, 1, 120, 90, 8);
  WallWindow window(wall, {.vsync = false, .title = "keys test"});
  window.present({0, 0.0, 1, false}, {distinct_picture(0, 120, 90), distinct_picture(1, 120, 90)});
  testing::XClient x(xvfb->display());
  const unsigned long id = x.wait_for_window("keys test", 5s);
  ASSERT_NE(id, 0u) << "the wall window never appeared on " << xvfb->display();
  EXPECT_EQ(window.poll_events(), UserAction::None);
  const std::pair<const char*, UserAction> keys[] = {{"space", UserAction::PauseToggled},
                                                     {"s", UserAction::Screenshot},
                                                     {"q", UserAction::Quit},
                                                     {"Escape", UserAction::Quit}};
  for (const auto& [key, action] : keys) {
    x.type(id, key);
    EXPECT_EQ(next_action(window), action) << "key " << key;
    EXPECT_EQ(window.poll_events(), UserAction::None) << "key " << key << " reported twice";
  }
  // Keys without a meaning do nothing.
  x.type(id, "a");
  x.type(id, "Return");
  std::this_thread::sleep_for(100ms);
  EXPECT_EQ(window.poll_events(), UserAction::None);
}

TEST(Keys, QOnAFullscreenDisplayQuits) {
  L2_START_XVFB(xvfb, 640, 480);
  MonitorWall shown(grid_wall(1, 1, 160, 120, 0), {.vsync = false, .title = "keys fs"});
  shown.present({0, 0.0, 1, false}, {distinct_picture(0, 160, 120)});
  testing::XClient x(xvfb->display());
  const unsigned long id = x.wait_for_window("keys fs - display 0", 5s);
  ASSERT_NE(id, 0u);
  x.type(id, "q");
  EXPECT_EQ(next_action(shown), UserAction::Quit);
}

}  // namespace
}  // namespace l2
