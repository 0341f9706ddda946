// The word a user probably meant, for "did you mean" in error lines.
#include "base/nearest_word.hpp"

#include <gtest/gtest.h>

#include <string>

namespace l2 {
namespace {

TEST(NearestWord, FindsTheKeyATypoMeant) {
  const std::initializer_list<std::string_view> keys = {"kind", "tile_width", "tile_height"};
  EXPECT_EQ(nearest_word("tile_hieght", keys), "tile_height");  // two letters swapped
  EXPECT_EQ(nearest_word("tile_heigt", keys), "tile_height");   // one missing
  EXPECT_EQ(nearest_word("tile_widthh", keys), "tile_width");   // one added
  EXPECT_EQ(nearest_word("kynd", keys), "kind");                // one wrong
}

TEST(NearestWord, SaysNothingWhenNoKeyIsClose) {
  EXPECT_EQ(nearest_word("colour", {"kind", "width"}), std::nullopt);
  EXPECT_EQ(nearest_word("", {"kind"}), std::nullopt);
  EXPECT_EQ(nearest_word(std::string(100000, 'k'), {"kind"}), std::nullopt);  // bounded
}

TEST(NearestWord, ListsTheChoices) {
  EXPECT_EQ(word_list({"kind", "tile_width"}), "kind, tile_width");
  EXPECT_EQ(word_list({}), "");
}

}  // namespace
}  // namespace l2
