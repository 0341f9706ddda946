// The verifier as users meet it: `tilelayout --scanout` frames, corrupted with the strip-header
// encoder, checked by `lightning2_emu route --verify`; and `tilelayout --verify` in one step.
#include <gtest/gtest.h>

#include <fstream>

#include "base/child_process.hpp"
#include "image/png_io.hpp"
#include "tilelayout/test_pattern.hpp"
#include "verify/check_picture.hpp"
#include "verify_test_wall.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using verify_test::header_at;
using verify_test::set_header;

// Far longer than any of these commands takes, even under the sanitizers: one that hangs
// fails its test instead of holding up the suite.
constexpr std::chrono::minutes kCommandBound{2};

struct Result {
  int status;
  std::string out;
};

Result run(const std::string& command) {
  const Finished f = run_shell(command, kCommandBound);
  return {f.status.shell_code(), f.out};
}

std::string hex(const StripHeader& h) {
  return fmt::format("{:012x}", encode(h));
}

class VerifyCli : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() /
                 ("l2-verify-cli-" +
                  std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::path wall = dir / "wall.toml";
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(wall) << verify_test::kWallToml;
    const Result r = run(fmt::format("{} --wall {} --scanout {}", TILELAYOUT_EXE, wall.string(),
                                     (dir / "scan").string()));
    ASSERT_EQ(r.status, 0) << r.out;
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path scan(int n) const { return dir / "scan" / fmt::format("scanout-{}.png", n); }
  Result route_verify(const std::string& frames) const {
    return run(fmt::format("{} route --wall {} --verify --out {} {}", L2_EMU_EXE, wall.string(),
                           (dir / "out").string(), frames));
  }
};

TEST_F(VerifyCli, RouteVerifyNamesSwappedHeaders) {
  RgbImage frame = read_png(scan(0));
  const StripHeader to_display_0 = header_at(frame, 2, 5), to_display_1 = header_at(frame, 36, 5);
  set_header(frame, 2, 5, to_display_1);
  set_header(frame, 36, 5, to_display_0);
  write_png(scan(0), frame);
  const Result r = route_verify(scan(0).string() + " " + scan(1).string());
  EXPECT_EQ(r.status, 4) << r.out;
  const std::string out = (dir / "out").string();
  EXPECT_EQ(r.out,
            "routed 2 inputs to 2 displays (1x1 boards: 4 inputs, 8 displays, inputs up to "
            "1280x1024); 0 strip errors; wrote " +
                out +
                "\n"
                "display 0 (64x32) wrong: 2048 planned pixels: 2016 right, 0 missing, 32 "
                "misplaced; 0 written twice, 0 behind mullions\n"
                "display 1 (64x32) wrong: 2048 planned pixels: 2016 right, 0 missing, 32 "
                "misplaced; 0 written twice, 0 behind mullions\n"
                "input 0: 2 strips not as planned for pipeserver 0, first at row 5 column 2: "
                "found d=1 x=0 y=5 w=32, planned d=0 x=0 y=5 w=32\n"
                "misplaced runs: 2\n"
                "  input 0 row 5 from column 36 (header " +
                hex(to_display_0) +
                " COPY f=0 d=0 x=0 y=5 w=32): 32x1 pixels landed on display 0 at 0,5, belong on "
                "display 1 at 0,5\n"
                "  input 0 row 5 from column 2 (header " +
                hex(to_display_1) +
                " COPY f=0 d=1 x=0 y=5 w=32): 32x1 pixels landed on display 1 at 0,5, belong on "
                "display 0 at 0,5\n"
                "routing wrong: 2 of 2 displays wrong, 0 inputs with refused strips, 1 not as "
                "planned\n"
                "wrote " +
                out + "/verify-<d>.png: the displays, wrong pixels marked\n");
  const RgbImage picture = read_png(dir / "out/verify-0.png");
  EXPECT_EQ(picture.at(0, 5), kMisplacedColour);
  EXPECT_EQ(picture.at(31, 5), kMisplacedColour);
  EXPECT_EQ(picture.at(32, 5).r, test_pattern(0, 32, 5).r / 4);  // right: dimmed to a quarter
  EXPECT_EQ(picture.at(64, 5), kMarginColour);
}

TEST_F(VerifyCli, RouteVerifyForgottenInput) {
  const Result r = route_verify(scan(0).string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("\ndisplay 1 (64x32) wrong: 2048 planned pixels: 1024 right, 1024 "
                       "missing, 0 misplaced; 0 written twice, 0 behind mullions\n"
                       "frames given for 1 of the wall's 2 pipeservers: input 1 sent nothing\n"
                       "routing wrong: 2 of 2 displays wrong, 0 inputs with refused strips\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(read_png(dir / "out/verify-1.png").at(40, 0), kMissingColour);
}

// Crossed cables: every strip still lands right, but input 0 carries pipeserver 1's frame.
TEST_F(VerifyCli, RouteVerifyNamesCrossedCables) {
  const Result r = route_verify(scan(1).string() + " " + scan(0).string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("\ninput 0 carries pipeserver 1's frame, not its own: a crossed cable"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\nrouting wrong: 0 of 2 displays wrong, 0 inputs with refused strips, 2 "
                       "not as planned\n"),
            std::string::npos)
      << r.out;
}

TEST_F(VerifyCli, RouteVerifyOfTheScanOutIsClean) {
  const Result r = route_verify(scan(0).string() + " " + scan(1).string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\nrouting right: every planned pixel in place on 2 displays\n"),
            std::string::npos)
      << r.out;
}

TEST_F(VerifyCli, RouteVerifyNeedsAWall) {
  const Result r = run(fmt::format("{} route --displays 64x32 --verify --out {} {}", L2_EMU_EXE,
                                   (dir / "out").string(), scan(0).string()));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--verify requires --wall"), std::string::npos) << r.out;
}

TEST_F(VerifyCli, TilelayoutVerifyScansOutRoutesAndChecks) {
  const Result r = run(fmt::format("{} --wall {} --verify {} --parity 1", TILELAYOUT_EXE,
                                   wall.string(), (dir / "v").string()));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\ndisplay 0 (64x32) right: 2048 planned pixels: 2048 right, 0 missing, 0 "
                       "misplaced; 0 written twice, 0 behind mullions\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\nrouting right: every planned pixel in place on 2 displays\n"),
            std::string::npos)
      << r.out;
  for (const char* name : {"scanout-0.png", "scanout-1.png", "display-0.png", "display-1.png",
                           "verify-0.png", "verify-1.png"}) {
    EXPECT_TRUE(fs::exists(dir / "v" / name)) << name;
  }
  EXPECT_EQ(read_png(dir / "v/display-1.png").at(40, 7), test_pattern(1, 40, 7));
}

// The sort-last example wall (DEPTH strips only): clean as scanned out, wrong with two
// layers exchanged on the bus (the tie rule of spec §7 then keeps the wrong colours).
TEST_F(VerifyCli, DepthLayersVerifyCleanOnlyInBusOrder) {
  const std::string depth_wall = std::string(L2_WALLS_DIR) + "/sort-last-512x384.toml";
  const fs::path v = dir / "depth";
  Result r = run(fmt::format("{} --wall {} --verify {}", TILELAYOUT_EXE, depth_wall, v.string()));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\ndisplay 0 (512x384) right: 196608 planned pixels: 196608 right, 0 "
                       "missing, 0 misplaced; 0 written twice, 0 behind mullions\n"),
            std::string::npos)
      << r.out;
  r = run(fmt::format("{} route --wall {} --verify --out {} {} {} {}", L2_EMU_EXE, depth_wall,
                      (dir / "swapped").string(), (v / "scanout-1.png").string(),
                      (v / "scanout-0.png").string(), (v / "scanout-2.png").string()));
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("\nrouting wrong: 1 of 1 displays wrong, 0 inputs with refused strips\n"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace l2
