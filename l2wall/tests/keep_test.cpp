#include <gtest/gtest.h>

#include <stdexcept>

#include "live_run.hpp"

namespace l2 {
namespace {

TEST(ParseKeep, Words) {
  EXPECT_TRUE(parse_keep("every").keeps(3, 10));
  EXPECT_TRUE(parse_keep("last").keeps(9, 10));
  EXPECT_FALSE(parse_keep("last").keeps(8, 10));
  EXPECT_FALSE(parse_keep("none").keeps(9, 10));
}

TEST(ParseKeep, FrameList) {
  const KeepSet keep = parse_keep("0,4,7");
  EXPECT_TRUE(keep.keeps(0, 10));
  EXPECT_TRUE(keep.keeps(4, 10));
  EXPECT_FALSE(keep.keeps(5, 10));
  EXPECT_FALSE(keep.keeps(9, 10));
}

TEST(ParseKeep, BadItemIsNamed) {
  try {
    parse_keep("1,x2");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--keep: 'x2' is not every, last, none or a frame number");
  }
  EXPECT_THROW(parse_keep("3,-1"), std::invalid_argument);
  EXPECT_THROW(parse_keep("3,"), std::invalid_argument);
}

}  // namespace
}  // namespace l2
