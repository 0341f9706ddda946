// A session's displays against its reference render (`pipeserver --reference`), for the tests
// that run sessions through `l2wall run` (live_run_session_test.cpp, live_run_vnc_test.cpp).
#pragma once

#include "l2wall/frame_stamp.hpp"
#include "wall_run.hpp"

namespace l2::testing_support {

// The reference of every display for frame `frame`, rendered by the pipeserver program (a test
// process that shows windows through l2wall's libraries draws through another libGL than
// OSMesa's).
inline std::vector<RgbImage> references(const fs::path& session, int frame) {
  const fs::path dir =
      session.parent_path() / fmt::format("ref-{}-{}", session.stem().string(), frame);
  const Finished f = run({L2_PIPESERVER_PATH, "--scene", "session", "--session", session.string(),
                          "--frame", std::to_string(frame), "--reference", dir.string()},
                         120s);
  EXPECT_TRUE(f.status.ok()) << f.out;
  std::vector<RgbImage> out;
  for (std::size_t d = 0; d < default_wall().displays.size(); ++d)
    out.push_back(read_png(dir / fmt::format("display-{}.png", d)));
  return out;
}

// Frame `frame`'s displays as the run kept them must equal the reference render; a pipeserver
// without a stamp strip marks its first tile's first pixel with the frame, which is checked and
// set to the reference's pixel first.
inline void expect_references(const WallRun& run, int frame, const fs::path& session) {
  const TileLayout layout = plan_layout(default_wall());
  const std::vector<RgbImage> reference = references(session, frame);
  std::vector<RgbImage> shown;
  for (std::size_t d = 0; d < layout.wall.displays.size(); ++d)
    shown.push_back(
        read_png(run.out() / fmt::format("frame-{}", frame) / fmt::format("display-{}.png", d)));
  for (const PipeserverPlan& plan : layout.pipeservers) {
    if (plan.has_stamp_strip()) continue;
    const DisplayTile& t = plan.tiles.front().tile;
    RgbImage& d = shown[static_cast<std::size_t>(t.display)];
    const Rgb p = d.at(t.on_display.x, t.on_display.y);
    const std::uint8_t rgb[3] = {p.r, p.g, p.b};
    EXPECT_EQ(decode_stamp(rgb), frame);
    d.set(t.on_display.x, t.on_display.y,
          reference[static_cast<std::size_t>(t.display)].at(t.on_display.x, t.on_display.y));
  }
  for (std::size_t d = 0; d < shown.size(); ++d)
    EXPECT_TRUE(shown[d] == reference[d]) << "frame " << frame << " display " << d;
}

}  // namespace l2::testing_support
