// `pipeserver --live` with the load balancer's control channel (balance/): the tiles' times go
// out as TIMES after every frame, and the next frame is rendered in the LAYOUT sent back. A
// real pipeserver process, a real pty for READY, a real socket pair, its DVI link read back.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "balance/control_channel.hpp"
#include "base/child_process.hpp"
#include "dvi_link/dvi_link.hpp"
#include "strip_headers/strip_header.hpp"
#include "sync_backchannel/back_channel.hpp"
#include "sync_backchannel/pty_pair.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

StripHeader header_in(const FrameView& f, int x, int y) {
  const std::uint8_t* p = f.row(y).data() + static_cast<std::size_t>(x) * 3;
  const auto h = decode(header_value(p, p + 3));
  EXPECT_TRUE(h.has_value()) << "no valid header at " << x << "," << y;
  return h.value_or(StripHeader{});
}

TEST(LiveControl, TheNextFrameIsRenderedInTheLayoutSentBack) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2-control-{}", getpid());
  fs::create_directories(dir);
  const fs::path wall_file = dir / "wall.toml";
  std::ofstream(wall_file) << "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 160\nheight = 120\n"
                              "[tiling]\nkind = \"grid\"\ntile_width = 80\ntile_height = 120\n"
                              "[pipeservers]\ncount = 2\nframebuffer_width = 200\n"
                              "framebuffer_height = 130\n";
  const Wall wall = load_wall(wall_file);
  // Frame 1: pipeserver 0 renders two tiles instead of one, in two framebuffer rows.
  LayoutMessage next{1, {{0, 0, 80, 60}, {80, 0, 80, 60}, {0, 60, 160, 60}}, {0, 1, 0}, {}};
  const PipeserverPlan plan1 = plan_from_message(wall, next).pipeservers[0];
  ASSERT_EQ(plan1.tiles.size(), 2u);
  ASSERT_EQ(plan1.tiles[1].tile.on_display.w, 160);
  ASSERT_EQ(plan1.tiles[1].fb_y, 60);

  auto [ours, theirs] = control_socket_pair();
  PtyPair pty = PtyPair::open();
  BackChannel ready(pty.master());
  const std::string link = dvi_link_name(fmt::format("ctl{}", getpid()));
  ChildProcess host({PIPESERVER_EXE, "--live", "--wall", wall_file.string(), "--pipeserver", "0",
                     "--frames", "2", "--scene", "patches", "--link", link, "--backchannel",
                     pty.slave_path(), "--control-fd", std::to_string(theirs.fd()), "--report",
                     (dir / "host.log").string()});
  { SocketControlChannel child_end = std::move(theirs); }  // the child holds its own copy

  const TimesMessage t0 = decode_times(ours.receive_line(30s).value_or("no TIMES 0"));
  EXPECT_EQ(t0.frame, 0);
  EXPECT_EQ(t0.pipeserver, 0);
  ASSERT_EQ(t0.seconds.size(), 1u);
  EXPECT_GT(t0.seconds[0], 0.0);
  ours.send_line(encode(next));
  const TimesMessage t1 = decode_times(ours.receive_line(30s).value_or("no TIMES 1"));
  EXPECT_EQ(t1.frame, 1);
  EXPECT_EQ(t1.seconds.size(), 2u);

  ready.send_ready(0);  // frame 1 goes out once frame 0 is on the displays
  DviLinkReader reader = DviLinkReader::open(link);
  std::optional<FrameView> frame;
  for (int i = 0; i < 1000 && !(frame && frame->sequence == 2); ++i) {
    std::this_thread::sleep_for(10ms);
    frame = reader.latest();
  }
  ASSERT_TRUE(frame && frame->sequence == 2) << "frame 1 was not published";
  // Its headers are frame 1's layout: the 80-wide tile, and the 160-wide one below it.
  for (const PackedTile& p : plan1.tiles) {
    const StripHeader h = header_in(*frame, p.fb_x - 2, p.fb_y);
    EXPECT_EQ(h.op, StripOp::Copy);
    EXPECT_TRUE(h.frame);
    EXPECT_EQ(h.x, p.tile.on_display.x);
    EXPECT_EQ(h.y, p.tile.on_display.y);
    EXPECT_EQ(h.width, p.tile.on_display.w);
  }
  ready.send_ready(1);
  const auto status = host.wait_for(30s);
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(status->ok()) << status->describe();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
