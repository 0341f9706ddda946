// The strip_headers executable as a user runs it: exact output and exit status.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/child_process.hpp"
#include "image/png_io.hpp"
#include "strip_headers/extension_word.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2 {
namespace {

// Far longer than any of these commands takes, even under the sanitizers: one that hangs
// fails its test instead of holding up the suite.
constexpr std::chrono::minutes kCommandBound{2};

struct Result {
  int status;
  std::string out;  // stdout and stderr
};

Result run(const std::string& args) {
  const Finished f = run_shell(std::string(STRIP_HEADERS_EXE) + " " + args, kCommandBound);
  return {f.status.shell_code(), f.out};
}

TEST(StripHeadersCli, ExtEncodesTheSpecVectors) {
  EXPECT_EQ(run("ext --kind key --key 000000").out, "100000000032\n");
  EXPECT_EQ(run("ext --kind key --key 00FF00").out, "1000ff000019\n");
  EXPECT_EQ(run("ext --kind key --key ff00ff").out, "10ff00ff0034\n");
  EXPECT_EQ(run("ext --kind depth").out, "200000000064\n");
  EXPECT_EQ(run("ext --kind 3").out, "300000000056\n");
}

TEST(StripHeadersCli, DecodeExtNamesTheWordOrWhyItIsRefused) {
  const Result key = run("decode --ext 1000FF000019");
  EXPECT_EQ(key.out, "1000ff000019: KEY key=00ff00\n");
  EXPECT_EQ(key.status, 0);
  EXPECT_EQ(run("decode --ext 200000000064").out, "200000000064: DEPTH\n");
  const Result check = run("decode --ext 1000ff000018");
  EXPECT_EQ(check.out, "1000ff000018: check error (expected check 19, got 18)\n");
  EXPECT_EQ(check.status, 1);
  const Result kind = run("decode --ext 300000000056");
  EXPECT_EQ(kind.out, "300000000056: EXT unsupported: kind 3 (KEY is 1, DEPTH 2)\n");
  EXPECT_EQ(kind.status, 1);
  // Words whose check is right (computed by hand): bit 41 set; a DEPTH with key 000010.
  EXPECT_EQ(run("decode --ext 1200000000f6").out,
            "1200000000f6: EXT unsupported: bits 43..40 or 15..8, which must be 0, are not\n");
  EXPECT_EQ(run("decode --ext 200000100033").out,
            "200000100033: EXT unsupported: DEPTH with key 000010 (must be 0)\n");
  EXPECT_EQ(run("decode e18320640190").out, "e18320640190: EXT f=1 d=3 x=100 y=200 w=50\n");
}

// A 19-byte PPM that declares 16384x16384 pixels (805 MB as RGB): refused from its header in
// one line, before the picture is read (read_scanned_frame's check runs before any pixel is
// allocated; lightning2_emu's cli test measures that peak for route), as route refuses it.
TEST(StripHeadersCli, DumpRefusesAPictureNoBoardTakesBeforeReadingIt) {
  const std::filesystem::path huge =
      std::filesystem::temp_directory_path() / fmt::format("strip-headers-huge-{}.ppm", getpid());
  std::ofstream(huge, std::ios::binary) << "P6\n16384 16384\n255\n" << std::string(30, '\0');
  const Result r = run("dump " + huge.string());
  std::filesystem::remove(huge);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "strip_headers: " + huge.string() +
                       ": a 16384x16384 picture is no scanned-out frame: a board takes at most "
                       "4096x4096 (spec §5)\n");
}

TEST(StripHeadersCli, DumpShowsKeyAndDepthStrips) {
  RgbImage frame(40, 3);
  auto put = [&](int x, int y, std::uint64_t value) {
    write_header_pixels(value, frame.row(y).data() + x * 3, 3);
  };
  auto ext = [](int display, int x, int y, int width) {
    StripHeader h = StripHeader::copy(true, display, x, y, width);
    h.op = StripOp::Ext;
    return encode(h);
  };
  put(0, 0, ext(3, 100, 7, 5));  // word 2..3, colour 4..8
  put(2, 0, encode(Extension::key_colour(0x00FF00)));
  put(9, 0, encode(StripHeader::copy(true, 1, 2, 3, 3)));  // strip 11..13, END at 14
  put(0, 1, ext(4, 0, 8, 6));                              // word 2..3, colour 4..9, depth 10..15
  put(2, 1, encode(Extension::depth()));
  put(16, 1, ext(4, 6, 8, 2));
  put(18, 1, 0x300000000056);  // kind 3
  const auto path = std::filesystem::temp_directory_path() / "strip_headers_cli_dump.png";
  write_png(path, frame);
  const Result r = run("dump " + path.string());
  EXPECT_EQ(r.out,
            "row 0:  [0] EXT f=1 d=3 x=100 y=7 w=5 KEY key=00ff00  [9] COPY f=1 d=1 x=2 "
            "y=3 w=3\n"
            "row 1:  [0] EXT f=1 d=4 x=0 y=8 w=6 DEPTH  errors=1\n" +
                path.string() +
                ": 40x3, 3 strips (COPY 1, SKIP 0, KEY 1, DEPTH 1); check errors 0, EXT "
                "unsupported 1, zero width 0, truncations 0\n");
  EXPECT_EQ(r.status, 1);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace l2
