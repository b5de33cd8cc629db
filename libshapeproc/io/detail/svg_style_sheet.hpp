// SVG style declarations (`style` attributes) and embedded style sheets (`<style>`) with simple
// selectors, for the SVG reader.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shapeproc::io {

// Property–value pairs in order, names lower-cased, `!important` dropped.
using Declarations = std::vector<std::pair<std::string, std::string>>;

Declarations parse_declarations(std::string_view text);

// A rule of an embedded style sheet with a simple selector: `tag`, `.class`, `tag.class`, `#id`.
struct CssRule {
  std::string tag, class_name, id;
  int specificity = 0;
  int order = 0;
  Declarations declarations;
};

// The rules of a style sheet with simple selectors (others, at-rules and comments skipped);
// `order` numbers them across sheets and is advanced.
std::vector<CssRule> parse_style_sheet(std::string text, int& order);

}  // namespace shapeproc::io
