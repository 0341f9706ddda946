#include "tilelayout/toml_text.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(TomlQuoted, EscapesWhatTomlForbidsAndKeepsTheRestOnOneLine) {
  EXPECT_EQ(toml_quoted("plain"), "\"plain\"");
  EXPECT_EQ(toml_quoted("say \"hi\" \\ bye"), "\"say \\\"hi\\\" \\\\ bye\"");
  EXPECT_EQ(toml_quoted("a\nb\tc"), "\"a\\nb\\tc\"");
  EXPECT_EQ(toml_quoted(std::string("\x1b[2J\x7f", 5)), "\"\\u001B[2J\\u007F\"");
  EXPECT_EQ(toml_quoted("Salle \xc3\xa9t\xc3\xa9"), "\"Salle \xc3\xa9t\xc3\xa9\"");
  EXPECT_EQ(toml_quoted(""), "\"\"");
}

}  // namespace
}  // namespace l2
