#include "command_line/size_text.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(SizeText, TwoNumbersJoinedByX) {
  const auto size = parse_size_text("1280x1024");
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 1280);
  EXPECT_EQ(size->height, 1024);
  EXPECT_EQ(parse_size_text("16384X2")->height, 2);
  EXPECT_EQ(parse_size_text("0x0")->width, 0);  // a range is the caller's to check
}

TEST(SizeText, AnythingElseIsRefused) {
  // 4294967360 wrapped to 64 through sscanf's %d in vizserver --displays.
  for (const char* bad :
       {"4294967360x64", "64x4294967360", "-1x64", "64x-1", "+64x64", " 64x64", "64 x 64", "64x64x",
        "64x64 ", "64x", "x64", "64", "", "0x40x40", "sixty-fourx64"}) {
    EXPECT_FALSE(parse_size_text(bad)) << "'" << bad << "' was taken";
  }
}

TEST(ListItems, EveryItemAsWrittenEmptyOnesIncluded) {
  EXPECT_EQ(list_items("1280x1024,640x480"), (std::vector<std::string>{"1280x1024", "640x480"}));
  EXPECT_EQ(list_items("a"), (std::vector<std::string>{"a"}));
  EXPECT_EQ(list_items(""), (std::vector<std::string>{""}));
  EXPECT_EQ(list_items("a,"), (std::vector<std::string>{"a", ""}));
  EXPECT_EQ(list_items(",,b"), (std::vector<std::string>{"", "", "b"}));
  EXPECT_EQ(list_items("1;2", ';'), (std::vector<std::string>{"1", "2"}));
}

}  // namespace
}  // namespace l2
