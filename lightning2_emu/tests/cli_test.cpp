// The lightning2_emu executable on real files: PNG frames in, PNG displays and JSON out.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "base/child_process.hpp"
#include "image/png_io.hpp"
#include "lightning2_emu/frame_builder.hpp"
#include "measured_run.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using testing::FrameBuilder;

// Far longer than any of these commands takes, even under the sanitizers: one that hangs
// fails its test instead of holding up the suite.
constexpr std::chrono::minutes kCommandBound{2};

struct Result {
  int status;
  std::string output;
};

Result run(const std::string& args) {
  const Finished f = run_shell(std::string(L2_EMU_EXE) + " " + args, kCommandBound);
  return {f.status.shell_code(), f.out};
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

class Cli : public ::testing::Test {
 protected:
  fs::path dir =
      fs::temp_directory_path() /
      ("l2emu-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(Cli, RouteWritesEveryDisplayAndAReport) {
  // Input 0 fills display 0 (20x3) row 0 and display 1 (10x2) row 1; input 1 has a bad header.
  FrameBuilder in0(40, 4), in1(40, 4);
  const int x = in0.copy(0, 0, 0, 0, 0, 20);
  in0.copy(x, 0, 1, 0, 1, 10);
  in1.raw_header(0, 0, 0x000000000001);
  write_png(dir / "in0.png", in0.image());
  write_png(dir / "in1.png", in1.image());
  const Result r =
      run("route --displays 20x3,10x2 --background 102030 --out " + (dir / "out").string() + " " +
          (dir / "in0.png").string() + " " + (dir / "in1.png").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const RgbImage d0 = read_png(dir / "out/display-0.png");
  const RgbImage d1 = read_png(dir / "out/display-1.png");
  ASSERT_EQ(d0.width(), 20);
  ASSERT_EQ(d1.height(), 2);
  for (int k = 0; k < 20; ++k) EXPECT_EQ(d0.at(k, 0), testing::pattern(0, k, 0));
  for (int k = 0; k < 10; ++k) EXPECT_EQ(d1.at(k, 1), testing::pattern(1, k, 1));
  EXPECT_EQ(d0.at(3, 2), (Rgb{0x10, 0x20, 0x30}));
  const auto report = read_json(dir / "out/report.json");
  EXPECT_EQ(report["displays"][0]["covered_pixels"], 20);
  EXPECT_EQ(report["displays"][1]["strips"], 1);
  EXPECT_EQ(report["inputs"][0]["copy_strips"], 2);
  EXPECT_EQ(report["inputs"][1]["errors"]["check_errors"], 1);
  EXPECT_EQ(report["errors"]["total"], 1);
  EXPECT_EQ(report["mesh"]["inputs"], 4);
}

// report.json lists the input files; a name that is not UTF-8 (byte 0xff) made the JSON library
// throw after the file was opened, leaving an empty report and exit 1. Bad bytes are written as
// U+FFFD.
TEST_F(Cli, RouteReportsAnInputNameThatIsNotUtf8) {
  FrameBuilder in(40, 4);
  in.copy(0, 0, 0, 0, 0, 20);
  const fs::path input = dir / "in\xff.png";
  write_png(input, in.image());
  const Result r =
      run("route --displays 20x3 --out " + (dir / "out").string() + " " + input.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto report = read_json(dir / "out/report.json");
  ASSERT_EQ(report["input_files"].size(), 1u);
  EXPECT_EQ(report["input_files"][0], (dir / "in\xef\xbf\xbd.png").string());
  EXPECT_EQ(report["displays"][0]["covered_pixels"], 20);
  EXPECT_EQ(report["inputs"][0]["copy_strips"], 1);
}

TEST_F(Cli, RouteRefusesInputsLargerThanTheBoardLimit) {
  write_png(dir / "big.png", RgbImage(1281, 10));
  const Result r = run("route --displays 100x100 --out " + (dir / "o").string() + " " +
                       (dir / "big.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("big.png: input 0 is 1281x10, larger than the board limit 1280x1024"),
            std::string::npos)
      << r.output;
}

// Tiny pictures whose headers claim 16384x16384 pixels (805 MB as RGB): route allocated the
// whole picture (a GIF 1 GB more inside OpenImageIO) before it found the frame larger than a
// board takes. Refused on the header now: the peak stays that of routing a small frame.
TEST_F(Cli, RouteRefusesAHugeFrameBeforeAllocatingIt) {
  constexpr unsigned char kPng[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x40, 0x00, 0x08, 0x02, 0x00, 0x00,
      0x00, 0x26, 0xaa, 0x87, 0xd3, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
      0x9c, 0x63, 0x60, 0x80, 0x00, 0x00, 0x00, 0x08, 0x00, 0x01, 0xb7, 0x58, 0x73, 0x95,
      0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  constexpr unsigned char kBmp[] = {
      0x42, 0x4d, 0x54, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x36, 0x00, 0x00, 0x00,
      0x28, 0x00, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x01, 0x00,
      0x18, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x13, 0x0b, 0x00, 0x00,
      0x13, 0x0b, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  constexpr unsigned char kTga[] = {0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                                    0x00, 0x00, 0x00, 0x00, 0x40, 0x00, 0x40, 0x18, 0x00};
  const auto bytes = [](const unsigned char* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size) + std::string(30, '\0');
  };
  const std::vector<std::pair<std::string, std::string>> pictures = {
      {"huge.png", bytes(kPng, sizeof kPng)},
      {"huge.bmp", bytes(kBmp, sizeof kBmp)},
      {"huge.tga", bytes(kTga, sizeof kTga)},
      {"huge.ppm", std::string("P6\n16384 16384\n255\n") + std::string(30, '\0')},
      {"huge.gif", std::string("GIF89a\x00\x40\x00\x40\x00\x00\x00,\x00\x00\x00\x00\x00\x40\x00"
                               "\x40\x00\x02\x02\x44\x01\x00;",
                               29)},
  };
  // The baseline reads a BMP: through the image codec, whose libraries a PNG (read with libpng
  // alone) does not load.
  FrameBuilder small(40, 4);
  small.copy(0, 0, 0, 0, 0, 20);
  write_png(dir / "small.bmp", small.image());
  const auto route = [&](const std::string& picture) {
    return process_run::run({L2_EMU_EXE, "route", "--displays", "20x3", "--out",
                             (dir / "out").string(), (dir / picture).string()},
                            dir / "output.txt");
  };
  const process_run::Ended baseline = route("small.bmp");
  ASSERT_EQ(baseline.code, 0) << baseline.output;
  for (const auto& [name, content] : pictures) {
    std::ofstream(dir / name, std::ios::binary) << content;
    const process_run::Ended m = route(name);
    EXPECT_EQ(m.code, 1) << name;
    EXPECT_EQ(m.output, "lightning2_emu: " + (dir / name).string() + ": input 0 is 16384x16384, " +
                            "larger than the board limit 1280x1024\n");
    // Allowance for what reading a file's header takes; the picture would be 786432 KB.
    EXPECT_LT(m.peak_kib, baseline.peak_kib + 100 * 1024) << name;
  }
}

TEST_F(Cli, RouteRefusesInputsAndDisplaysBeyondTheMesh) {
  write_png(dir / "a.png", RgbImage(8, 8));
  std::string five;
  for (int i = 0; i < 5; ++i) five += " " + (dir / "a.png").string();
  Result r = run("route --displays 10x10 --mesh 1x1 --out " + (dir / "o").string() + five);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("5 inputs given, the mesh"), std::string::npos) << r.output;
  std::string nine = "10x10";
  for (int d = 1; d < 9; ++d) nine += ",10x10";
  r = run("route --displays " + nine + " --mesh 1x1 --out " + (dir / "o").string() + " " +
          (dir / "a.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("display 8 is beyond the mesh"), std::string::npos) << r.output;
  r = run("route --displays 10y10 --out " + (dir / "o").string() + " " + (dir / "a.png").string());
  EXPECT_EQ(r.status, 2);  // a usage error
  EXPECT_NE(r.output.find("--displays: display 0: '10y10' is not WIDTHxHEIGHT"), std::string::npos)
      << r.output;
}

TEST_F(Cli, SequenceShowsEachFrameOneRefreshLater) {
  // Two inputs, three frames each; input 1 tears its second frame once.
  auto frame = [](int input, int k, bool torn) {
    FrameBuilder b(32, 4);
    const Rgb c{static_cast<std::uint8_t>(50 * k + 10), static_cast<std::uint8_t>(input), 0};
    b.copy_fill(0, 0, 0, 0, input, 8, c, k % 2);
    b.copy_fill(0, 1, 0, 8, input, 8, c, torn ? !(k % 2) : k % 2);
    return b.image();
  };
  for (int i = 0; i < 2; ++i) fs::create_directories(dir / ("in" + std::to_string(i)));
  write_png(dir / "in0/f0.png", frame(0, 0, false));
  write_png(dir / "in0/f1.png", frame(0, 1, false));
  write_png(dir / "in0/f2.png", frame(0, 1, false));
  write_png(dir / "in1/f0.png", frame(1, 0, false));
  write_png(dir / "in1/f1.png", frame(1, 1, true));
  write_png(dir / "in1/f2.png", frame(1, 1, false));
  const Result r = run("sequence --displays 16x2 --out " + (dir / "out").string() + " " +
                       (dir / "in0").string() + " " + (dir / "in1").string());
  ASSERT_EQ(r.status, 0) << r.output;
  auto shown = [&](int t) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.png", t);
    return read_png(dir / "out/display-0" / name).at(0, 0);
  };
  EXPECT_EQ(shown(0), Rgb{});            // nothing yet
  EXPECT_EQ(shown(1), (Rgb{10, 0, 0}));  // frame 0
  EXPECT_EQ(shown(2), (Rgb{10, 0, 0}));  // frame 1 torn on input 1: still frame 0
  EXPECT_EQ(shown(3), (Rgb{60, 0, 0}));  // frame 1
  const auto report = read_json(dir / "out/report.json");
  EXPECT_EQ(report["ticks"], 4);
  EXPECT_EQ(report["frames_torn"], 1);
  // Predicted from the last layout: every frame after an input's first, except input 1's
  // frame after its torn one. The torn frame itself was predicted, and found different.
  EXPECT_EQ(report["frames_predicted"], 5);
  EXPECT_EQ(report["predictions_missed"], 1);
  EXPECT_NE(r.output.find("(5 predicted from their input's last layout, 1 of them found "
                          "different and parsed)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(report["groups"][0]["swaps"], 2);
  EXPECT_EQ(report["tick_log"][1]["frames"][1], "torn");
  // READY in the refresh each frame completes in, a refresh before its swap (spec §6.4).
  const std::vector<std::vector<int>> ready = {{0, 1}, {}, {0, 1}, {}};
  for (int t = 0; t < 4; ++t) {
    EXPECT_EQ(report["tick_log"][t]["ready_inputs"].get<std::vector<int>>(), ready[t]) << t;
    EXPECT_EQ(report["tick_log"][t]["swapped_groups"].size(), t == 1 || t == 3 ? 1u : 0u) << t;
  }

  // Again into the same folder, two refreshes: the display folder holds this run's frames
  // only (frame-0002 and -0003 of the run above stayed), and nothing else is touched.
  std::ofstream(dir / "out/display-0/notes.txt") << "mine";
  std::ofstream(dir / "out/display-0/frame-final.png") << "mine";
  const Result again = run("sequence --displays 16x2 --ticks 2 --out " + (dir / "out").string() +
                           " " + (dir / "in0").string() + " " + (dir / "in1").string());
  ASSERT_EQ(again.status, 0) << again.output;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "out/display-0"))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame-0000.png", "frame-0001.png", "frame-final.png",
                                             "notes.txt"}));
}

// tilelayout --scanout, then route --wall: every display shows the test pattern where the plan
// put tiles, and wall.png places the displays as on the wall.
TEST_F(Cli, RouteWithAWallRebuildsTheTilelayoutScanout) {
  const std::string wall_file = std::string(L2_WALLS_DIR) + "/kd-2x2.toml";
  const std::string scan_dir = (dir / "scan").string();
  ASSERT_EQ(std::system((std::string(TILELAYOUT_EXE) + " --wall " + wall_file + " --scanout " +
                         scan_dir + " > /dev/null")
                            .c_str()),
            0);
  const Wall wall = load_wall(wall_file);
  const TileLayout layout = plan_layout(wall);
  std::string inputs;
  for (int s = 0; s < wall.pipeserver_count; ++s) {
    inputs += " " + scan_dir + "/scanout-" + std::to_string(s) + ".png";
  }
  const Result r = run("route --wall " + wall_file + " --out " + (dir / "out").string() + inputs);
  ASSERT_EQ(r.status, 0) << r.output;
  std::vector<RgbImage> expected;
  for (const Display& d : wall.displays) expected.emplace_back(d.width, d.height);
  for (const DisplayTile& t : layout.tiles) {
    for (int y = t.on_display.y; y < t.on_display.bottom(); ++y) {
      for (int x = t.on_display.x; x < t.on_display.right(); ++x) {
        expected[t.display].set(x, y, test_pattern(t.display, x, y));
      }
    }
  }
  for (const Display& d : wall.displays) {
    const RgbImage shown = read_png(dir / "out" / ("display-" + std::to_string(d.id) + ".png"));
    EXPECT_EQ(shown, expected[d.id]) << "display " << d.id;
  }
  const RgbImage picture = read_png(dir / "out/wall.png");
  EXPECT_GE(picture.width(), wall.canvas_width);
  EXPECT_GE(picture.height(), wall.canvas_height);
  for (const Display& d : wall.displays) {
    EXPECT_EQ(picture.at(d.canvas_x + d.width / 2, d.canvas_y + d.height / 3),
              expected[d.id].at(d.width / 2, d.height / 3));
  }
  const auto report = read_json(dir / "out/report.json");
  EXPECT_EQ(report["errors"]["total"], 0);
}

// A file that cannot be written (a folder in its place): the error named it and only said
// OpenImageIO's "Could not open file", after display-0 and -1 were written and with an earlier
// run's report.json left beside them. Now: why, and what OUT holds of this run; an earlier
// report.json is removed first, so a report.json in OUT belongs to a complete run.
TEST_F(Cli, RouteSaysWhichFileFailedAndWhatOutHolds) {
  FrameBuilder in(40, 4);
  in.copy(0, 0, 0, 0, 0, 20);
  write_png(dir / "in.png", in.image());
  const fs::path out = dir / "out";
  fs::create_directories(out / "display-2.png");
  std::ofstream(out / "report.json") << "{}";
  const Result r = run("route --displays 20x3,20x3,20x3 --out " + out.string() + " " +
                       (dir / "in.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "lightning2_emu: " + out.string() +
                          "/display-2.png: cannot write: a folder, not a file; " + out.string() +
                          " holds only part of this run: display-0.png, display-1.png, no "
                          "report.json\n");
  EXPECT_EQ(read_png(out / "display-0.png").width(), 20);
  EXPECT_EQ(read_png(out / "display-1.png").width(), 20);
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

TEST_F(Cli, RouteRefusesAReportFolderBeforeWritingAnything) {
  FrameBuilder in(40, 4);
  write_png(dir / "in.png", in.image());
  const fs::path out = dir / "out";
  fs::create_directories(out / "report.json");
  const Result r =
      run("route --displays 20x3 --out " + out.string() + " " + (dir / "in.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "lightning2_emu: " + out.string() +
                          "/report.json: cannot write: a folder, not a file\n");
  EXPECT_FALSE(fs::exists(out / "display-0.png"));
}

TEST_F(Cli, SequenceSaysWhichPictureFailedAndWhatOutHolds) {
  fs::create_directories(dir / "in0");
  FrameBuilder in(40, 4);
  in.copy(0, 0, 0, 0, 0, 20);
  write_png(dir / "in0/f0.png", in.image());
  const fs::path out = dir / "out";
  fs::create_directories(out / "display-1/frame-0001.png");
  std::ofstream(out / "report.json") << "{}";
  const Result r =
      run("sequence --displays 20x3,20x3 --out " + out.string() + " " + (dir / "in0").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "lightning2_emu: " + out.string() +
                          "/display-1/frame-0001.png: cannot write: a folder, not a file; " +
                          out.string() +
                          " holds only part of this run: the pictures of refresh 0 and part of "
                          "refresh 1, no report.json\n");
  EXPECT_TRUE(fs::exists(out / "display-0/frame-0000.png"));
  EXPECT_TRUE(fs::exists(out / "display-1/frame-0000.png"));
  EXPECT_TRUE(fs::exists(out / "display-0/frame-0001.png"));
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

// A damaged PNG: libpng printed its own line ("libpng error: IHDR: CRC error") before ours, and
// ours went on over two more lines of OpenImageIO's. Now ours is the only line.
TEST_F(Cli, DamagedPngIsOneLineOfOurs) {
  FrameBuilder in(40, 4);
  in.copy(0, 0, 0, 0, 0, 20);
  write_png(dir / "in.png", in.image());
  std::string bytes;
  {
    std::ifstream file(dir / "in.png", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(file), {});
  }
  std::ofstream(dir / "truncated.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::string bad_crc = bytes;
  bad_crc[29] = static_cast<char>(bad_crc[29] ^ 0xff);  // the first byte of IHDR's CRC
  std::ofstream(dir / "bad-crc.png", std::ios::binary) << bad_crc;

  for (const auto& [file, why] :
       {std::pair<std::string, std::string>{"truncated.png", "the PNG file ends early (truncated)"},
        {"bad-crc.png", "a damaged PNG (IHDR: CRC error)"}}) {
    const Result r =
        run("route --displays 20x3 --out " + (dir / "out").string() + " " + (dir / file).string());
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output,
              "lightning2_emu: " + (dir / file).string() + ": cannot read: " + why + "\n");
  }
}

// A grey PNG or a JPEG as an input frame was read as RGB and routed, its headers counted as
// check errors (exit 0). Neither file can hold strip headers; they are refused, one line each.
TEST_F(Cli, GreyAndJpegFramesAreRefused) {
  FrameBuilder in(40, 4);
  in.copy(0, 0, 0, 0, 0, 20);
  write_png(dir / "frame.jpg", in.image());  // a JPEG, by its name
  constexpr unsigned char kGreyPng[] = {
      // 2x1 grey: 7, 200 (as in image/tests/png_io_test.cpp)
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
      0x00, 0xd1, 0x49, 0x20, 0x56, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
      0x9c, 0x63, 0x60, 0x3f, 0x01, 0x00, 0x00, 0xd9, 0x00, 0xd0, 0xd7, 0xa6, 0x22, 0x3c,
      0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  std::ofstream(dir / "grey.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(kGreyPng), sizeof kGreyPng);

  Result r = run("route --displays 20x3 --out " + (dir / "out").string() + " " +
                 (dir / "grey.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "lightning2_emu: " + (dir / "grey.png").string() +
                          ": a grayscale picture (one colour channel) cannot hold strip headers: "
                          "a header is 48 bits in the R, G and B bytes of two pixels\n");
  EXPECT_FALSE(fs::exists(dir / "out/display-0.png"));

  const std::string jpeg_refused =
      ": a JPEG picture cannot hold strip headers: the lossy "
      "compression changes pixel bytes (save frames as PNG)\n";
  r = run("route --displays 20x3 --out " + (dir / "out").string() + " " +
          (dir / "frame.jpg").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "lightning2_emu: " + (dir / "frame.jpg").string() + jpeg_refused);

  fs::create_directories(dir / "in0");
  fs::copy_file(dir / "frame.jpg", dir / "in0/f0.jpg");
  r = run("sequence --displays 20x3 --out " + (dir / "out").string() + " " +
          (dir / "in0").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "lightning2_emu: " + (dir / "in0/f0.jpg").string() + jpeg_refused);
  EXPECT_FALSE(fs::exists(dir / "out/report.json"));
}

TEST_F(Cli, HelpNamesBothCommands) {
  const Result r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("route"), std::string::npos);
  EXPECT_NE(r.output.find("sequence"), std::string::npos);
}

}  // namespace
}  // namespace l2
