#include "command_line/printable.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(Printable, KeepsPrintableTextAndOtherScripts) {
  EXPECT_EQ(printable("wall 2x2, kd \"tiles\" 100%"), "wall 2x2, kd \"tiles\" 100%");
  EXPECT_EQ(printable("Wand \xc3\xa4 \xe6\x98\xbe\xe7\xa4\xba \xf0\x9f\x96\xa5"),
            "Wand \xc3\xa4 \xe6\x98\xbe\xe7\xa4\xba \xf0\x9f\x96\xa5");
}

TEST(Printable, ControlCharactersBecomeVisibleEscapes) {
  EXPECT_EQ(printable("\x1b[2J\x1b]0;owned\x07name"), "\\x1b[2J\\x1b]0;owned\\x07name");
  EXPECT_EQ(printable(std::string_view("a\0b\n\t\r\x7f", 7)), "a\\x00b\\n\\t\\r\\x7f");
  // C1 controls: CSI as one byte (not UTF-8) and as UTF-8 (U+009B).
  EXPECT_EQ(printable("\x9b"
                      "31m \xc2\x9b"
                      "31m"),
            "\\x9b31m \\xc2\\x9b31m");
}

TEST(Printable, BytesThatAreNotUtf8AreEscaped) {
  EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(printable("\xc3"), "\\xc3");                    // cut short
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a UTF-16 surrogate
}

TEST(Printable, EscapingTwiceChangesNothing) {
  const std::string once = printable("\x1b[31mred\xc2\x9b\xff\\n");
  EXPECT_EQ(once, "\\x1b[31mred\\xc2\\x9b\\xff\\n");
  EXPECT_EQ(printable(once), once);
}

TEST(Printable, C1ControlsAndBrokenUtf8AreEscapedByteByByte) {
  EXPECT_EQ(printable("\xc2\x9b"
                      "31m"),
            "\\xc2\\x9b31m");                                        // CSI as U+009B
  EXPECT_EQ(printable("\x9b"), "\\x9b");                             // CSI as a raw byte
  EXPECT_EQ(printable("\xc3"), "\\xc3");                             // truncated
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");                    // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a surrogate
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(printable("\xe2\x82"
                      "x"),
            "\\xe2\\x82x");
}

}  // namespace
}  // namespace l2
