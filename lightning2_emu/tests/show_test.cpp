// `lightning2_emu sequence --show` on a private Xvfb: every refresh of a captured sequence on
// screen, read back from the X server and compared with the display pictures the run wrote.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "base/child_process.hpp"
#include "displays/xvfb_server.hpp"
#include "image/png_io.hpp"
#include "lightning2_emu/frame_builder.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using testing::FrameBuilder;

struct Result {
  int status = -1;
  std::string output;
  double seconds = 0;
};

// Far longer than any of these commands takes, even under the sanitizers: one that hangs
// fails its test instead of holding up the suite.
constexpr std::chrono::minutes kCommandBound{2};

Result run(const std::string& args) {
  const auto t0 = std::chrono::steady_clock::now();
  const Finished f = run_shell(std::string(L2_EMU_EXE) + " " + args, kCommandBound);
  Result r;
  r.output = f.out;
  r.status = f.status.shell_code();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

class Show : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!::l2::testing::XvfbServer::installed()) GTEST_SKIP() << "Xvfb is not installed";
    xvfb = std::make_unique<::l2::testing::XvfbServer>(640, 480);
    fs::remove_all(dir);
    fs::create_directories(dir / "in0");
    fs::create_directories(dir / "in1");
    // Input i feeds display i (64x8 and 40x8): per row a strip of one colour that changes
    // with the frame, then a strip of the router-independent pattern.
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 2; ++i) {
        FrameBuilder b(72, 8);
        const Rgb colour{static_cast<std::uint8_t>(60 * k + 40), static_cast<std::uint8_t>(i * 90),
                         200};
        for (int y = 0; y < 8; ++y) {
          const int x = b.copy_fill(0, y, i, 0, y, 20, colour, k % 2);
          b.copy(x, y, i, 20, y, i == 0 ? 44 : 20, k % 2);
        }
        write_png(dir / fmt::format("in{}", i) / fmt::format("f{}.png", k), b.image());
      }
    }
  }
  void TearDown() override { fs::remove_all(dir); }

  std::string inputs() const { return (dir / "in0").string() + " " + (dir / "in1").string(); }

  fs::path dir = fs::temp_directory_path() / fmt::format("l2emu-show-{}", getpid());
  std::unique_ptr<::l2::testing::XvfbServer> xvfb;
};

TEST_F(Show, EveryRefreshOnScreenEqualsTheWrittenDisplaysAtTheRefreshRate) {
  const Result r = run(fmt::format(
      "sequence --displays 64x8,40x8 --out {} --show window --refresh 10 --show-readback {} {}",
      (dir / "out").string(), (dir / "screen").string(), inputs()));
  ASSERT_EQ(r.status, 0) << r.output;
  // 4 refreshes (3 frames and the one that shows the last), each up for 1/10 s.
  EXPECT_GE(r.seconds, 0.4) << r.output;
  for (int t = 0; t < 4; ++t) {
    for (int d = 0; d < 2; ++d) {
      const RgbImage written =
          read_png(dir / "out" / fmt::format("display-{}", d) / fmt::format("frame-{:04}.png", t));
      const RgbImage shown =
          read_png(dir / "screen" / fmt::format("frame-{}", t) / fmt::format("display-{}.png", d));
      EXPECT_TRUE(shown == written) << "refresh " << t << " display " << d;
    }
  }
  // Not trivially equal: the displays changed from refresh to refresh (spec §6: frame k shows
  // at refresh k+1, nothing before).
  const auto pixel = [&](int t) {
    return read_png(dir / "screen" / fmt::format("frame-{}", t) / "display-0.png").at(0, 3);
  };
  EXPECT_EQ(pixel(0), Rgb{});
  EXPECT_EQ(pixel(1), (Rgb{40, 0, 200}));
  EXPECT_EQ(pixel(3), (Rgb{160, 0, 200}));
}

TEST_F(Show, MonitorsWithFewerMonitorsThanDisplaysIsRefused) {
  const Result r = run(fmt::format("sequence --displays 64x8,40x8 --out {} --show monitors {}",
                                   (dir / "out").string(), inputs()));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output,
            "lightning2_emu: --displays: --show monitors needs one monitor per display: 2 "
            "displays, but GLFW sees 1 monitor: [0] \"screen\" 640x480 at (0,0)\n");
}

}  // namespace
}  // namespace l2
