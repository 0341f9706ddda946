// `l2wall run --renderer`: every pipeserver is started with it, says in its log what it decided
// on, and the summary says it; EGL forced runs on llvmpipe here and the displays show what
// OSMesa's show, byte for byte; `auto` (the default) picks OSMesa on a machine without a GPU and
// says why; an EGL that cannot render ends the run with each pipeserver's one line.
#include <gtest/gtest.h>

#include <regex>

#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

bool has_gpu_node() {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/dev/dri", ec))
    if (e.path().filename().string().rfind("renderD", 0) == 0) return true;
  return false;
}

const std::vector<std::string> kRun{"--scene",   "isosurface", "--frames", "3",
                                    "--refresh", "0",          "--keep",   "last"};

std::vector<std::string> with(std::vector<std::string> args, std::vector<std::string> more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(RunRenderer, EglShowsWhatOsMesaShowsAndTheSummarySaysWhichRendered) {
  if (has_gpu_node())
    GTEST_SKIP() << "this machine has a GPU's render node: EGL need not be llvmpipe";
  WallRun egl("renderer-egl", with(kRun, {"--renderer", "egl"}));
  ASSERT_TRUE(egl.wait(60s).ok()) << egl.output();
  WallRun osmesa("renderer-osmesa", with(kRun, {"--renderer", "osmesa"}));
  ASSERT_TRUE(osmesa.wait(60s).ok()) << osmesa.output();
  EXPECT_TRUE(std::regex_search(
      egl.output(),
      std::regex("\nrenderer: egl \\(llvmpipe [^\n]*, EGL device: Mesa's software device; "
                 "--renderer egl\\), on every pipeserver\n")))
      << egl.output();
  EXPECT_TRUE(std::regex_search(
      osmesa.output(),
      std::regex("\nrenderer: osmesa \\(llvmpipe [^\n]*; --renderer osmesa\\), on every "
                 "pipeserver\n")))
      << osmesa.output();
  for (int p = 0; p < 4; ++p) {
    EXPECT_EQ(slurp(egl.out() / fmt::format("pipeserver-{}.log", p)).rfind("renderer egl (", 0),
              0u);
  }
  for (int d = 0; d < 4; ++d) {
    const fs::path shown = fs::path("frame-2") / fmt::format("display-{}.png", d);
    EXPECT_TRUE(read_png(egl.out() / shown) == read_png(osmesa.out() / shown)) << shown;
  }
  expect_clean(egl);
  expect_clean(osmesa);
}

TEST(RunRenderer, AutoPicksOsMesaWithoutAGpuAndSaysWhy) {
  if (has_gpu_node()) GTEST_SKIP() << "this machine has a GPU's render node";
  WallRun run("renderer-auto", kRun);
  ASSERT_TRUE(run.wait(60s).ok()) << run.output();
  EXPECT_TRUE(std::regex_search(
      run.output(), std::regex("\nrenderer: osmesa \\(llvmpipe [^\n]*; auto: no GPU: EGL finds "
                               "only Mesa's software device \\(llvmpipe\\)\\), on every "
                               "pipeserver\n")))
      << run.output();
  expect_clean(run);
}

// Mesa's EGL without its drivers: eglInitialize fails on every display.
TEST(RunRenderer, AnEglThatCannotRenderEndsTheRunInOneLineAPipeserver) {
  WallRun run("renderer-no-egl", with(kRun, {"--renderer", "egl"}), {}, false,
              "env LIBGL_DRIVERS_PATH=/nonexistent");
  EXPECT_FALSE(run.wait(60s).ok());
  const std::string output = run.output();
  // Every pipeserver fails so; whichever ends first ends the run, and the others may be stopped
  // before they print.
  EXPECT_TRUE(
      std::regex_search(output, std::regex("pipeserver [0-3]: --renderer egl: no EGL display can "
                                           "render here: Mesa's software device: eglInitialize "
                                           "failed \\(EGL_NOT_INITIALIZED")))
      << output;
  EXPECT_NE(output.find("l2wall: pipeserver "), std::string::npos) << output;
  EXPECT_NE(output.find("\nrenderer: not said (no pipeserver got as far as rendering)\n"),
            std::string::npos)
      << output;
  expect_clean(run);
}

}  // namespace
}  // namespace l2
