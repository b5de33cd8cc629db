// SVG style declarations (`style` attributes) and embedded style sheets (`<style>`) with simple
// selectors, for the SVG reader.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
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

// The rules of a document's style sheets, found by the key their selector needs (an id, a class,
// or neither), so that matching an element looks at the rules that name its id or its classes
// and the few that name neither, not at every rule: linear in the document, not quadratic.
class StyleSheet {
 public:
  void add(std::vector<CssRule> rules);
  // The rules that match an element of `tag`, `id` and `classes` (the class attribute, names
  // separated by spaces), by specificity, then order.
  std::vector<const CssRule*> matching(std::string_view tag, std::string_view id,
                                       std::string_view classes) const;
  bool empty() const { return rules_.empty(); }

 private:
  std::vector<CssRule> rules_;
  std::unordered_map<std::string, std::vector<std::size_t>> by_id_, by_class_;
  std::vector<std::size_t> others_;  // tag-only or universal selectors
};

}  // namespace shapeproc::io
