// `l2wall golden` on a rendered entry, with real pipeserver processes: update makes a new
// entry's images and records this Mesa; images recorded as made by another Mesa are compared
// within the tolerance, and the output says so; with this Mesa the same pixel fails; stopped by
// SIGTERM, it ends its live run first. A small wall of its own (two pipeservers, one 320x240
// display, DVI path only) keeps the live runs short; the repository's rendered entries, on both
// paths, run in the CTest l2wall_golden_check.
#include <signal.h>

#include <algorithm>
#include <fstream>
#include <thread>

#include "base/process_table.hpp"
#include "golden/golden_manifest.hpp"
#include "golden_cli.hpp"
#include "image/png_io.hpp"
#include "pipeserver/gl_context.hpp"

namespace l2 {
namespace {

using namespace l2::test;

const char* kSmallWall = R"toml(name = "one small display, two pipeservers"
[[display]]
id = 0
width = 320
height = 240
x = 0
y = 0
[tiling]
kind = "grid"
tile_width = 160
tile_height = 120
[pipeservers]
count = 2
framebuffer_width = 324
framebuffer_height = 240
)toml";

const char* kSmallEntry = R"toml([[entry]]
name = "small-bunny"
kind = "rendered"
wall = "walls/small.toml"
scene = "mesh"
frame = 1
paths = ["dvi"]
tolerance = { differing_percent = 0.01, beyond_one_percent = 0.003 }
)toml";

// The small wall under `root` and a manifest of its one rendered entry, no images yet; returns
// the options that point `l2wall golden` at them.
std::string small_entry(const fs::path& root, const fs::path& goldens, const fs::path& out) {
  fs::create_directories(root / "walls");
  std::ofstream(root / "walls/small.toml") << kSmallWall;
  fs::remove_all(goldens);
  fs::create_directories(goldens);
  std::ofstream(goldens / "manifest.toml") << kSmallEntry;
  return "--goldens " + quote(goldens) + " --root " + quote(root) + " --out " + quote(out) + " ";
}

TEST_F(GoldenCli, UpdateRecordsThisMesaAndAnotherMesaIsComparedWithinTheTolerance) {
  const fs::path root = dir_ / "root";
  const std::string where = small_entry(root, goldens(), out());

  // A new entry: update makes its image and records the GL that made it.
  const Result made = l2wall("update " + where);
  ASSERT_EQ(made.code, 0) << made.output;
  EXPECT_NE(made.output.find("1 image written, manifest rewritten"), std::string::npos)
      << made.output;
  const GlInfo gl = gl_info();
  GoldenManifest manifest = load_manifest(goldens() / "manifest.toml");
  ASSERT_EQ(manifest.entries.size(), 1u);
  EXPECT_EQ(manifest.entries[0].gl_version, gl.version);
  EXPECT_EQ(manifest.entries[0].gl_renderer, gl.renderer);
  EXPECT_EQ(manifest.entries[0].mesa, gl.mesa_version());
  const RgbImage made_image = read_png(golden("small-bunny", 0));
  EXPECT_EQ(made_image.width(), 320);

  // One golden pixel changed, and the images said to come from another Mesa: within tolerance.
  RgbImage changed = made_image;
  changed.set(20, 10, Rgb{255, 255, 254});
  write_png(golden("small-bunny", 0), changed);
  manifest.entries[0].mesa = "0.1.0";
  manifest.entries[0].gl_version = "4.5 (Compatibility Profile) Mesa 0.1.0";
  std::ofstream(goldens() / "manifest.toml") << format_manifest(manifest);
  const Result other = l2wall("check " + where);
  EXPECT_EQ(other.code, 0) << other.output;
  EXPECT_NE(other.output.find("small-bunny: golden images made with Mesa 0.1.0 (" + gl.renderer +
                              "), this is Mesa " + gl.mesa_version() + " (" + gl.renderer +
                              "): compared within the tolerance"),
            std::string::npos)
      << other.output;
  EXPECT_NE(other.output.find("small-bunny: emulator vs golden image: 1 of 76800 pixels differ"),
            std::string::npos)
      << other.output;

  // The same pixel with the images recorded as this Mesa's: exact, so it fails.
  manifest.entries[0].mesa = gl.mesa_version();
  manifest.entries[0].gl_version = gl.version;
  std::ofstream(goldens() / "manifest.toml") << format_manifest(manifest);
  const Result same = l2wall("check " + where);
  EXPECT_EQ(same.code, 1) << same.output;
  EXPECT_NE(same.output.find("small-bunny display 0: emulator vs golden image: 1 pixel differs "
                             "(1 by more than one level)"),
            std::string::npos)
      << same.output;
  EXPECT_EQ(same.output.find("compared within the tolerance"), std::string::npos);
  EXPECT_TRUE(read_png(out() / "small-bunny/display-0-actual.png") == made_image);
}

// The same wall re-tiled (80-pixel-wide tiles): the picture is the same, but pipeserver 1's
// frame stamp moved from (160,0) to (80,0). Those two pixels are said to be stamps and left
// out; any other pixel still fails.
TEST_F(GoldenCli, StampsMovedByAReTilingAreLeftOutAndSaidSo) {
  const fs::path root = dir_ / "root";
  const std::string where = small_entry(root, goldens(), out());
  const Result made = l2wall("update " + where);
  ASSERT_EQ(made.code, 0) << made.output;

  std::string retiled = kSmallWall;
  retiled.replace(retiled.find("tile_width = 160"), 16, "tile_width = 80");
  std::ofstream(root / "walls/small.toml") << retiled;
  const Result check = l2wall("check " + where);
  EXPECT_EQ(check.code, 0) << check.output;
  EXPECT_NE(check.output.find("small-bunny: 2 pixels differ from the golden images only by frame "
                              "1's stamp (the first pixel of each pipeserver's first tile, moved "
                              "by another tiling): left out of the comparison"),
            std::string::npos)
      << check.output;

  // A real difference besides: still a failure.
  RgbImage changed = read_png(golden("small-bunny", 0));
  changed.set(20, 10, Rgb{255, 255, 254});
  write_png(golden("small-bunny", 0), changed);
  const Result failed = l2wall("check " + where);
  EXPECT_EQ(failed.code, 1) << failed.output;
  EXPECT_NE(failed.output.find("small-bunny display 0: emulator vs golden image: 1 pixel differs"),
            std::string::npos)
      << failed.output;
}

// A process whose command line holds `part` and every one of `words`, each a whole argument.
pid_t process_with(const std::vector<std::string>& words, const std::string& part = "") {
  for (const pid_t p : processes_with_command_line(part)) {
    const std::string cmdline = process_command_line(p);
    if (std::all_of(words.begin(), words.end(), [&](const std::string& w) {
          return cmdline.find(std::string(1, '\0') + w + '\0') != std::string::npos;
        }))
      return p;
  }
  return 0;
}

// `l2wall golden` stopped (SIGTERM to it alone, as `kill` sends it) while its entry's live run
// runs: it ends that run first, which ends its pipeservers and removes its shared memory, then
// says it was stopped and exits as by the signal. The live run is held (SIGSTOP) while golden is
// signalled, so the run is surely under way and still running when golden hears it.
TEST_F(GoldenCli, AStoppedGoldenEndsItsLiveRunFirst) {
  const fs::path root = dir_ / "root";
  std::string where = small_entry(root, goldens(), out());
  std::string entry = kSmallEntry;
  entry.replace(entry.find("frame = 1"), 9, "frame = 100000");
  std::ofstream(goldens() / "manifest.toml") << entry;
  ChildProcess golden({L2WALL_PATH, "golden", "update", "--goldens", goldens().string(), "--root",
                       root.string(), "--out", out().string()},
                      {}, Capture{.out = true, .err = true});
  pid_t run = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline && !golden.poll()) {
    if (run == 0) run = process_with({"run", "--no-progress"}, out().string());
    if (run != 0 && fs::exists(fmt::format("/dev/shm/l2-{}-in1", run))) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_NE(run, 0) << "no live run seen";
  ASSERT_TRUE(fs::exists(fmt::format("/dev/shm/l2-{}-in1", run))) << "its links never opened";
  ASSERT_EQ(kill(run, SIGSTOP), 0);
  ASSERT_EQ(kill(golden.pid(), SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(kill(run, SIGCONT), 0);
  const std::optional<ExitStatus> ended = golden.wait_for(std::chrono::seconds(60));
  ASSERT_TRUE(ended) << "l2wall golden did not end within 60 s of SIGTERM";
  EXPECT_FALSE(process_running(run)) << "its live run outlived it";
  EXPECT_EQ(ended->signal, SIGTERM) << ended->describe();
  const Finished said = golden.finish(std::chrono::seconds(5));
  EXPECT_NE(said.err.find("l2wall golden: stopped by signal 15 (Terminated)\n"), std::string::npos)
      << said.err << said.out;
  for (int i = 0; i < 2; ++i) {
    const std::string link = fmt::format("/l2-{}-in{}", run, i);
    EXPECT_EQ(process_with({"--link", link}), 0) << "pipeserver " << i << " left";
    EXPECT_FALSE(fs::exists("/dev/shm" + link)) << link << " left";
  }
}

}  // namespace
}  // namespace l2
