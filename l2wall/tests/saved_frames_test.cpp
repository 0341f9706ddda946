#include <gtest/gtest.h>

#include <stdexcept>

#include "live_run.hpp"

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
  o.vizserver = "vizserver";
  o.frames = 3;
  o.keep = "0,7";
  EXPECT_EQ(run_options_error(o),
            std::optional<std::string>("--keep: frame 7 is past the last frame (--frames 3 "
                                       "renders 0..2)"));
  o.keep = "0,2";
  EXPECT_EQ(run_options_error(o), std::nullopt);
  o.keep = "1,x2";
  EXPECT_EQ(run_options_error(o),
            std::optional<std::string>("--keep: 'x2' is not every, last, none or a frame number"));
  o.keep = "every";
  o.compare = true;
  EXPECT_EQ(run_options_error(o), std::optional<std::string>("--compare needs --path both"));
  o.path = "both";
  EXPECT_EQ(run_options_error(o), std::nullopt);
  // A fault injected after the last frame never happened, and the run passed.
  o.drop_ready = 3;
  EXPECT_EQ(run_options_error(o),
            std::optional<std::string>("--drop-ready: frame 3 is past the last frame (--frames 3 "
                                       "renders 0..2)"));
  o.drop_ready = 2;
  o.inject_mismatch = 1;
  EXPECT_EQ(run_options_error(o), std::nullopt);
  o.compare = false;
  EXPECT_EQ(run_options_error(o), std::optional<std::string>("--inject-mismatch needs --compare"));
  // An address for a compositing server the DVI path does not start went unused, silently.
  RunOptions dvi;
  dvi.viz_port = 5000;
  EXPECT_EQ(run_options_error(dvi),
            std::optional<std::string>("--viz-host and --viz-port need --path vizserver or both"));
  dvi.path = "vizserver";
  dvi.vizserver = "vizserver";
  EXPECT_EQ(run_options_error(dvi), std::nullopt);
}

}  // namespace
}  // namespace l2
