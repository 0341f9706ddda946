#include <gtest/gtest.h>

#include <stdexcept>

#include "l2wall/live_run.hpp"

namespace l2 {
namespace {

TEST(ParseSavedFrames, Words) {
  EXPECT_TRUE(parse_saved_frames("every").saves(3, 10));
  EXPECT_TRUE(parse_saved_frames("last").saves(9, 10));
  EXPECT_FALSE(parse_saved_frames("last").saves(8, 10));
  EXPECT_FALSE(parse_saved_frames("none").saves(9, 10));
}

TEST(ParseSavedFrames, FrameList) {
  const SavedFrames saved = parse_saved_frames("0,4,7");
  EXPECT_TRUE(saved.saves(0, 10));
  EXPECT_TRUE(saved.saves(4, 10));
  EXPECT_FALSE(saved.saves(5, 10));
  EXPECT_FALSE(saved.saves(9, 10));
}

TEST(ParseSavedFrames, BadItemIsNamed) {
  try {
    parse_saved_frames("1,x2");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--keep: 'x2' is not every, last, none or a frame number");
  }
  EXPECT_THROW(parse_saved_frames("3,-1"), std::invalid_argument);
  EXPECT_THROW(parse_saved_frames("3,"), std::invalid_argument);
}

TEST(RunOptionsError, KeptFramePastTheLastIsRefused) {
  // `l2wall run --frames 3 --keep 7` ran and silently kept nothing.
  RunOptions o;
  o.vizserver_program = "vizserver";
  o.frames = 3;
  o.keep = "0,7";
  EXPECT_EQ(run_options_error(o).reason(),
            "--keep: frame 7 is past the last frame (--frames 3 "
            "renders 0..2)");
  o.keep = "0,2";
  EXPECT_TRUE(run_options_error(o).ok());
  o.keep = "1,x2";
  EXPECT_EQ(run_options_error(o).reason(),
            "--keep: 'x2' is not every, last, none or a frame number");
  o.keep = "every";
  o.compare = true;
  EXPECT_EQ(run_options_error(o).reason(), "--compare needs --path both");
  o.path = PathChoice::Both;
  EXPECT_TRUE(run_options_error(o).ok());
  // A fault injected after the last frame never happened, and the run passed.
  o.drop_ready = 3;
  EXPECT_EQ(run_options_error(o).reason(),
            "--drop-ready: frame 3 is past the last frame (--frames 3 "
            "renders 0..2)");
  o.drop_ready = 2;
  o.inject_mismatch = 1;
  EXPECT_TRUE(run_options_error(o).ok());
  o.compare = false;
  EXPECT_EQ(run_options_error(o).reason(), "--inject-mismatch needs --compare");
  // An address for a compositing server the DVI path does not start went unused, silently.
  RunOptions dvi;
  dvi.viz_port = 5000;
  EXPECT_EQ(run_options_error(dvi).reason(),
            "--viz-host and --viz-port need --path vizserver or both");
  dvi.path = PathChoice::Vizserver;
  dvi.vizserver_program = "vizserver";
  EXPECT_TRUE(run_options_error(dvi).ok());
}

}  // namespace
}  // namespace l2
