// Touch over TUIO through `l2wall run --tuio`: a drag, a pinch and a tap sent as a tracker's
// bundles on loopback move, resize and raise a session's windows, each change on every display
// in the same frame: every display of the frames around each change equals the reference
// render of the windows as that frame's WINDOWS line places them (touch_run.hpp).
#include "touch_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

TEST(TouchOnTheWall, ADragAPinchAndATapSwitchInOneFrameOnEveryDisplay) {
  expect_touches_switch_in_one_frame("touch", "", {}, [](WallRun& run) { return run.wait(120s); });
}

// --tuio steers a session's windows: without one it is a usage error, before anything starts;
// an address already taken is one line.
TEST(TouchOnTheWall, RefusalsAreOneLine) {
  WallRun no_session("touch-no-session", {"--tuio", "127.0.0.1:0"});
  EXPECT_EQ(no_session.wait(60s).code, 2);  // a usage error, as --window-stdin's
  EXPECT_EQ(no_session.output(),
            "l2wall: --tuio moves a session's windows: it needs --scene session\n"
            "Run with --help for more information.\n");
  const ScratchDir dir("touch-taken");
  std::ofstream(dir / "session.toml") << "[[window]]\nsource = \"swap\"\nx = 0\ny = 0\n"
                                         "width = 10\nheight = 10\n";
  const Fd taken = bind_udp("127.0.0.1", 0);
  const int port = local_port(taken.get());
  WallRun in_use("touch-taken", {"--scene", "session", "--session", (dir / "session.toml").string(),
                                 "--tuio", fmt::format("127.0.0.1:{}", port)});
  EXPECT_EQ(in_use.wait(60s).code, 1);
  EXPECT_EQ(in_use.output(),
            fmt::format("l2wall: cannot bind udp 127.0.0.1:{}: Address already in use\n", port));
  expect_clean(in_use);
}

}  // namespace
}  // namespace l2
