// Style sheets: rules found by id, class or neither, in the cascade's order.
#include "libshapeproc/io/detail/svg_style_sheet.hpp"

#include <gtest/gtest.h>

namespace shapeproc::io {
namespace {

std::vector<std::string> fills(const std::vector<const CssRule*>& rules) {
  std::vector<std::string> out;
  for (const CssRule* r : rules) out.push_back(r->declarations.front().second);
  return out;
}

TEST(StyleSheet, MatchesByIdClassAndTagInSpecificityThenOrder) {
  int order = 0;
  StyleSheet sheet;
  sheet.add(parse_style_sheet(
      "/* a comment */ #e1 { fill: id } .a { fill: a } rect.a { fill: rect-a } rect { fill: rect }"
      " .b { fill: b } circle { fill: circle } * { fill: star } .a, .b { fill: a-or-b }",
      order));
  // `*` is no simple selector and is skipped; `.a, .b` gives two rules.
  EXPECT_EQ(fills(sheet.matching("rect", "e1", "a b")),
            (std::vector<std::string>{"rect", "a", "b", "a-or-b", "a-or-b", "rect-a", "id"}));
  EXPECT_EQ(fills(sheet.matching("circle", "", "b")),
            (std::vector<std::string>{"circle", "b", "a-or-b"}));
  EXPECT_EQ(fills(sheet.matching("path", "e2", "")), std::vector<std::string>{});
  EXPECT_EQ(fills(sheet.matching("rect", "", "c")), std::vector<std::string>{"rect"});
  EXPECT_EQ(order, 8);
}

TEST(StyleSheet, ManyRulesAndManyCommentsStayCheap) {
  // 20,000 classes and 20,000 comments: each element looks at its own class's rule only.
  std::string text;
  for (int i = 0; i < 20000; ++i)
    text += "/* " + std::to_string(i) + " */ .c" + std::to_string(i) + " { fill: f" +
            std::to_string(i) + " }\n";
  int order = 0;
  StyleSheet sheet;
  sheet.add(parse_style_sheet(text, order));
  EXPECT_EQ(order, 20000);
  for (int i = 0; i < 20000; i += 997)
    EXPECT_EQ(fills(sheet.matching("rect", "", "c" + std::to_string(i))),
              std::vector<std::string>{"f" + std::to_string(i)});
}

}  // namespace
}  // namespace shapeproc::io
