#include "l2wall/path_choice.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(PathChoice, ParsesTheThreeNamesAndNothingElse) {
  EXPECT_EQ(parse_path_choice("dvi"), PathChoice::Dvi);
  EXPECT_EQ(parse_path_choice("vizserver"), PathChoice::Vizserver);
  EXPECT_EQ(parse_path_choice("both"), PathChoice::Both);
  EXPECT_EQ(parse_path_choice("DVI"), std::nullopt);
  EXPECT_EQ(parse_path_choice("viz"), std::nullopt);
  EXPECT_EQ(parse_path_choice(""), std::nullopt);
}

TEST(PathChoice, NamesRoundTrip) {
  EXPECT_EQ(path_choice_name(PathChoice::Dvi), "dvi");
  EXPECT_EQ(path_choice_name(PathChoice::Vizserver), "vizserver");
  EXPECT_EQ(path_choice_name(PathChoice::Both), "both");
}

TEST(PathChoice, SaysWhichPathsRun) {
  EXPECT_TRUE(runs_dvi(PathChoice::Dvi));
  EXPECT_FALSE(runs_viz(PathChoice::Dvi));
  EXPECT_FALSE(runs_dvi(PathChoice::Vizserver));
  EXPECT_TRUE(runs_viz(PathChoice::Vizserver));
  EXPECT_TRUE(runs_dvi(PathChoice::Both));
  EXPECT_TRUE(runs_viz(PathChoice::Both));
}

}  // namespace
}  // namespace l2
