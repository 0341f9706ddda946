// The one DVI path driven over an in-memory Lightning-2 (FakeColumns, below): a display's picture
// is the frame number it holds, every pipeserver's strips reach every display, and a pipeserver
// publishes its next frame once READY for the last one arrives. What the path decides (which
// frames are new, when groups complete and swap, READY, the frame the displays show, swap lock)
// is checked against frame numbers the test knows, not against the path's own bookkeeping; on an
// active stereo wall, what the quad buffer shows in each refresh too.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>

#include "l2wall/dvi_path.hpp"
#include "l2wall/run_fault.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "sync_backchannel/ready_line.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

class FakeColumns final : public BoardColumns {
 public:
  FakeColumns(int displays, int pipeservers, int frames)
      : published(static_cast<std::size_t>(pipeservers), 0),
        back(static_cast<std::size_t>(displays), -1),
        done(back),
        front(back),
        frames_(frames) {}

  // What pipeserver `p` does on READY for `frame`: renders and publishes the next one.
  void ready(int p, std::uint64_t frame) {
    if (static_cast<int>(frame) + 1 < frames_)
      published[static_cast<std::size_t>(p)] = static_cast<int>(frame) + 1;
  }

  void open(PipeserverSet&, std::chrono::milliseconds, const RunWatch&) override {}
  bool take_in(PipeserverSet& pipeservers) override {
    bool fresh = false;
    for (LivePipeserver& h : pipeservers.all()) {
      const auto sequence =
          static_cast<std::uint64_t>(published[static_cast<std::size_t>(h.pipeserver)] + 1);
      fresh = fresh || sequence != h.sequence;
      h.sequence = sequence;
    }
    return fresh;
  }
  Status refresh(const Tick& tick, PipeserverSet&, const Decide& decide,
                 const std::function<void(std::span<const Observation>)>& took) override {
    if (!tick.swapped_groups.empty()) front = done;  // the wall has one group
    Observation o;
    o.refresh = tick.refresh;
    const std::uint64_t every_display = (std::uint64_t{1} << front.size()) - 1;
    for (std::size_t p = 0; p < published.size(); ++p) {
      o.inputs.push_back(
          {static_cast<int>(p), true, false, false, published[p] & 1, every_display, published[p]});
      o.stamps.push_back({static_cast<int>(p), front[0], front[0]});
    }
    for (std::size_t d = 0; d < front.size(); ++d) {
      const int skew = break_lock_at == tick.refresh && d == 1 ? 1 : 0;
      o.displays.push_back({static_cast<int>(d), front[d] + skew, 0});
    }
    if (tick.refresh == fail_at) {
      took(std::span(&o, 1));
      return Failure{"board column 0 did not answer; the displays keep frame " +
                     std::to_string(showing_)};
    }
    const ColumnRoute& r = decide(std::span(&o, 1));
    for (std::size_t p = 0; p < published.size(); ++p) {
      if (!r.route[p]) continue;
      for (int& b : back) b = std::max(b, published[p]);
    }
    if (!r.completed_groups.empty()) {
      done = back;
      back.assign(back.size(), -1);
    }
    return {};
  }
  // With `display_size` set, each display's picture is its front frame's own colour (an active
  // stereo wall's quad buffer copies them); else one pixel.
  DisplayPictures pictures() override {
    return [this](int id) -> const RgbImage& {
      if (display_size.first == 0) return picture_;
      return pictures_[id] = RgbImage(display_size.first, display_size.second,
                                      frame_colour(front[static_cast<std::size_t>(id)]));
    };
  }
  static Rgb frame_colour(int frame) { return Rgb{static_cast<std::uint8_t>(10 + frame), 0, 0}; }
  std::optional<DisplayPictures> shown() override { return pictures(); }
  void showing(int frame) override { showing_ = frame; }
  std::optional<std::uint64_t> routed_strips(int) const override { return 1; }
  std::string where() const override { return "in the test"; }

  std::vector<int> published;          // by pipeserver: the frame on its link
  std::vector<int> back, done, front;  // by display: the frame held
  std::int64_t fail_at = -1;           // the refresh a column does not answer
  std::int64_t break_lock_at = -1;     // the refresh display 1 shows another frame
  std::pair<int, int> display_size{0, 0};

 private:
  int frames_;
  int showing_ = -1;  // what the path said the displays keep
  RgbImage picture_{1, 1};
  std::map<int, RgbImage> pictures_;
};

// A back-channel that hands READY to the fake pipeserver and remembers it.
class FakeLine final : public ReadyChannel {
 public:
  FakeLine(FakeColumns& columns, int pipeserver) : columns_(columns), pipeserver_(pipeserver) {}
  bool send_ready(std::uint64_t frame) override {
    readies.push_back(frame);
    columns_.ready(pipeserver_, frame);
    return true;
  }
  int serve(std::chrono::milliseconds) override { return 0; }
  Result<ReadyAck> wait_ready(std::uint64_t, std::chrono::milliseconds, int) override {
    return Failure{"not a pipeserver's end"};
  }
  void send_sync_request(std::uint64_t) override {}
  const BackChannelCounts& counts() const override { return counts_; }

  std::vector<std::uint64_t> readies;

 private:
  FakeColumns& columns_;
  int pipeserver_;
  BackChannelCounts counts_;
};

// The built-in wall (four 640x480 displays, one swap group), or the same shown as active stereo.
Wall test_wall(StereoMode mode) {
  Wall wall = default_wall();
  wall.stereo.mode = mode;
  return wall;
}

struct PathRun {
  static constexpr int kFrames = 6;
  TileLayout layout;
  RunOptions options = [] {
    RunOptions o;
    o.frames = kFrames;
    o.refresh_hz = 0;
    return o;
  }();
  FakeColumns* columns = nullptr;
  std::vector<FakeLine*> lines;
  PipeserverSet pipeservers;
  std::unique_ptr<DviPath> path;
  std::vector<FrameRecord> records = std::vector<FrameRecord>(kFrames);
  RunWatch watch{[] {}, [] {}};

  explicit PathRun(StereoMode mode = StereoMode::Mono) : layout(plan_layout(test_wall(mode))) {
    auto owned =
        std::make_unique<FakeColumns>(static_cast<int>(layout.wall.displays.size()),
                                      static_cast<int>(layout.pipeservers.size()), kFrames);
    columns = owned.get();
    if (mode == StereoMode::Active) columns->display_size = {640, 480};
    path = std::make_unique<DviPath>(layout, options, std::move(owned));
    PipeserverLaunch launch;
    launch.frames = kFrames;
    pipeservers.attach(launch, layout, [&](int p) {
      PipeserverSet::RemoteEnd end;
      end.process = remote_pipeserver_process("in the test", [] { return false; });
      auto line = std::make_unique<FakeLine>(*columns, p);
      lines.push_back(line.get());
      end.channel = std::move(line);
      return end;
    });
    path->open(pipeservers, std::chrono::milliseconds(0), watch);
  }
  // Steps until a swap; its refresh and the lowest frame it shows.
  PathSwap next_swap() {
    for (int i = 0; i < 20; ++i) {
      if (const auto swap = path->step(0, pipeservers, records, watch)) return *swap;
    }
    throw std::runtime_error("no swap in 20 steps");
  }
};

TEST(DviPath, ShowsEveryFrameOneRefreshAfterItWasTakenIn) {
  PathRun run;
  ASSERT_EQ(make_swap_groups(display_specs(run.layout.wall)).size(), 1u);
  for (int frame = 0; frame < PathRun::kFrames; ++frame) {
    const PathSwap swap = run.next_swap();
    EXPECT_EQ(swap.lowest, frame);
    EXPECT_EQ(run.path->frame_shown(), frame);
    EXPECT_EQ(*swap.refresh, run.records[static_cast<std::size_t>(frame)].in_refresh + 1)
        << "frame " << frame;
    EXPECT_EQ(run.columns->front, std::vector<int>(run.columns->front.size(), frame));
  }
  for (const FakeLine* line : run.lines)
    EXPECT_EQ(line->readies, (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5}));
  for (const LivePipeserver& h : run.pipeservers.all()) EXPECT_EQ(h.accepted, 5);
}

TEST(DviPath, AColumnThatDoesNotAnswerIsNamedWithTheFrameTheDisplaysKeep) {
  PathRun run;
  run.next_swap();
  run.next_swap();  // frame 1 shown, swapped in refresh 2
  run.columns->fail_at = 4;
  try {
    run.next_swap();
    run.next_swap();
    FAIL() << "no fault";
  } catch (const RunFault& e) {
    // The refresh that failed swapped frame 3 in on the columns that answered: the line says
    // so, worded once the path knew it.
    EXPECT_STREQ(e.what(), "board column 0 did not answer; the displays keep frame 3");
  }
  EXPECT_EQ(run.path->frame_shown(), 3);
}

TEST(DviPath, ADisplayOfAGroupShowingAnotherFrameBreaksSwapLock) {
  PathRun run;
  run.next_swap();
  run.columns->break_lock_at = 3;
  try {
    for (int i = 0; i < 3; ++i) run.next_swap();
    FAIL() << "no fault";
  } catch (const RunFault& e) {
    EXPECT_STREQ(e.what(),
                 "swap lock broken in refresh 3: group 0: display 1 (rank 0) shows frame 3, "
                 "display 0 (rank 0) frame 2");
  }
}

TEST(DviPath, SummarySaysSwapLockHeldOnceEveryFrameIsShown) {
  PathRun run;
  EXPECT_EQ(run.path->summary_lines(), "");  // nothing proved before the end
  for (int frame = 0; frame < PathRun::kFrames; ++frame) run.next_swap();
  run.path->finish();
  EXPECT_EQ(run.path->summary_lines(),
            "swap lock: every display of each of 1 group(s) showed the same frame in all 7 "
            "refreshes, in the test\n");
}

// Eye frames 0-5 reach the displays in refreshes 1-6, one a refresh (the fake renders at once):
// the quad buffer shows pair 0 from refresh 2, when its right eye is in, and each pair whole,
// left in even refreshes, right in odd ones, refreshing on past the columns' last refresh until
// pair 2's right eye is shown. The pictures are the eye frames' own colours.
TEST(DviPath, AnActiveWallShowsEachPairLeftThenRight) {
  PathRun run(StereoMode::Active);
  for (int frame = 0; frame < PathRun::kFrames; ++frame) run.next_swap();
  run.path->finish();
  RunTotals totals;
  run.path->add_totals(totals);
  const auto csv = std::find_if(totals.path_files.begin(), totals.path_files.end(),
                                [](const auto& f) { return f.first == "stereo-refreshes.csv"; });
  ASSERT_NE(csv, totals.path_files.end());
  EXPECT_EQ(csv->second,
            "refresh,eye,frame\n0,none,\n1,none,\n2,left,0\n3,right,0\n4,left,1\n5,right,1\n"
            "6,left,2\n7,right,2\n");
  EXPECT_EQ(run.path->summary_lines(),
            "swap lock: every display of each of 1 group(s) showed the same frame in all 7 "
            "refreshes, in the test\n"
            "active stereo: 8 refreshes, every display alternated left/right every refresh from "
            "its first pair (refresh 2) on; pairs shown: 3 (0 repeated: no new pair ready), "
            "broken: 0; quad buffers: 24.6 MiB\n");
  // Refresh 7 shows eye frame 5 (frame 2's right eye) on every display.
  const DisplayPictures shown = *run.path->shown();
  for (int d = 0; d < 4; ++d)
    EXPECT_TRUE(shown(d) == RgbImage(640, 480, FakeColumns::frame_colour(5))) << "display " << d;
}

TEST(DviPath, FrameShownByStamps) {
  EXPECT_EQ(shown_by_stamps(5, 5, 4), 5);              // its last frame is on the displays
  EXPECT_EQ(shown_by_stamps(5, 9, 4), 4);              // the one before, still
  EXPECT_EQ(shown_by_stamps(5, 3, 7), 3);              // moved stamps: what the last spot shows
  EXPECT_EQ(shown_by_stamps(5, kStampNotHere, 2), 2);  // on another column: the other spot
  EXPECT_EQ(shown_by_stamps(0, kStampNotHere, kStampNotHere), std::nullopt);
}

}  // namespace
}  // namespace l2
