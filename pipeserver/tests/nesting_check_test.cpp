// How deep XML and brace-nested text go, counted as Assimp's recursive readers would nest:
// elements and braces only, never what a comment, CDATA, a declaration or a quoted value holds.
#include <gtest/gtest.h>

#include "nesting_check.hpp"

namespace l2::detail {
namespace {

TEST(Nesting, XmlCountsOpenElementsOnly) {
  // Levels: a 1, b 2, c 3 (on line 4); d is empty, the rest are not elements.
  const char* text =
      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n"
      "<!DOCTYPE a [<!ENTITY e \"<x><y><z>\">]>\n"
      "<a><!-- <q><q><q><q> -->\n"
      "<b k=\"1 > 0\" j='<'><c><d/><![CDATA[<e><f><g><h>]]></c></b>\n"
      "<b><c></c></b></a>\n";
  const Nesting n = xml_nesting(text);
  EXPECT_EQ(n.depth, 3);
  EXPECT_EQ(n.line, 4);
}

TEST(Nesting, StopsOnceItPassesTheLimit) {
  std::string text = "<r>";
  for (int i = 0; i < 5000; ++i) text += "\n<n>";
  const Nesting n = xml_nesting(text, 10);
  EXPECT_EQ(n.depth, 11);
  EXPECT_EQ(n.line, 11);
}

TEST(Nesting, NotXmlIsNothing) {
  EXPECT_EQ(xml_nesting("{\"a\": [<b>]}").depth, 0);
  EXPECT_EQ(xml_nesting("").depth, 0);
  // Cut short inside a tag or a comment: what was open counts, nothing is read past the end.
  EXPECT_EQ(xml_nesting("<a><b k=\"").depth, 2);
  EXPECT_EQ(xml_nesting("<a><!-- <b>").depth, 1);
}

TEST(Nesting, BracesOutsideQuotes) {
  const Nesting n = brace_nesting("xof 0302txt\nFrame a {\n \"{{{\" Frame b {\n}\n}\nc { }\n");
  EXPECT_EQ(n.depth, 2);
  EXPECT_EQ(n.line, 3);
}

}  // namespace
}  // namespace l2::detail
