#include "command_line/escape_for_terminal.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(EscapeForTerminal, PrintableTextAndUtf8PassThrough) {
  EXPECT_EQ(escape_for_terminal("wall 4 (left) = 1280x1024"), "wall 4 (left) = 1280x1024");
  EXPECT_EQ(escape_for_terminal("Z\xc3\xbcrich \xe2\x82\xac \xf0\x9f\x99\x82"),
            "Z\xc3\xbcrich \xe2\x82\xac \xf0\x9f\x99\x82");
}

TEST(EscapeForTerminal, ControlsAndEscapeSequencesAreWrittenOut) {
  // Clear screen, set the window title, a faked second line.
  EXPECT_EQ(escape_for_terminal("\x1b[2J\x1b]0;pwned\x07ok\r\nvizserver: done\t."),
            "\\x1b[2J\\x1b]0;pwned\\x07ok\\r\\nvizserver: done\\t.");
  EXPECT_EQ(escape_for_terminal(std::string_view("a\0b\x7f", 4)), "a\\x00b\\x7f");
}

TEST(EscapeForTerminal, EscapingTwiceChangesNothing) {
  const std::string once = escape_for_terminal("\x1b[31mred\xc2\x9b\xff\\n");
  EXPECT_EQ(once, "\\x1b[31mred\\xc2\\x9b\\xff\\n");
  EXPECT_EQ(escape_for_terminal(once), once);
}

TEST(EscapeForTerminal, C1ControlsAndBrokenUtf8AreEscapedByteByByte) {
  EXPECT_EQ(escape_for_terminal("\xc2\x9b"
                                "31m"),
            "\\xc2\\x9b31m");                                                  // CSI as U+009B
  EXPECT_EQ(escape_for_terminal("\x9b"), "\\x9b");                             // CSI as a raw byte
  EXPECT_EQ(escape_for_terminal("\xc3"), "\\xc3");                             // truncated
  EXPECT_EQ(escape_for_terminal("\xc0\xaf"), "\\xc0\\xaf");                    // overlong '/'
  EXPECT_EQ(escape_for_terminal("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a surrogate
  EXPECT_EQ(escape_for_terminal("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(escape_for_terminal("\xe2\x82"
                                "x"),
            "\\xe2\\x82x");
}

}  // namespace
}  // namespace l2
