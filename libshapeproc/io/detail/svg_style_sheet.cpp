#include "libshapeproc/io/detail/svg_style_sheet.hpp"

#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

Declarations parse_declarations(std::string_view text) {
  Declarations result;
  for (const std::string& item : split(text, ';')) {
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos) continue;
    std::string name = to_lower(trim(std::string_view(item).substr(0, colon)));
    std::string value(trim(std::string_view(item).substr(colon + 1)));
    if (const std::size_t bang = value.find("!important"); bang != std::string::npos) {
      value = std::string(trim(std::string_view(value).substr(0, bang)));
    }
    if (!name.empty()) result.emplace_back(std::move(name), std::move(value));
  }
  return result;
}

std::vector<CssRule> parse_style_sheet(std::string text, int& order) {
  // Strip comments.
  for (std::size_t start; (start = text.find("/*")) != std::string::npos;) {
    const std::size_t end = text.find("*/", start + 2);
    text.erase(start, end == std::string::npos ? std::string::npos : end + 2 - start);
  }
  std::vector<CssRule> rules;
  std::size_t pos = 0;
  while (true) {
    const std::size_t open = text.find('{', pos);
    if (open == std::string::npos) break;
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) break;
    const Declarations declarations =
        parse_declarations(std::string_view(text).substr(open + 1, close - open - 1));
    for (const std::string& raw : split(std::string_view(text).substr(pos, open - pos), ',')) {
      const std::string selector(trim(raw));
      if (selector.empty() || selector.front() == '@' ||
          selector.find_first_of(" >+~:[*") != std::string::npos) {
        continue;  // only simple selectors are supported
      }
      CssRule rule;
      if (selector.front() == '#') {
        rule.id = selector.substr(1);
        rule.specificity = 100;
      } else {
        const std::size_t dot = selector.find('.');
        rule.tag = selector.substr(0, dot);
        if (dot != std::string::npos) rule.class_name = selector.substr(dot + 1);
        rule.specificity = (rule.tag.empty() ? 0 : 1) + (rule.class_name.empty() ? 0 : 10);
      }
      rule.order = order++;
      rule.declarations = declarations;
      rules.push_back(std::move(rule));
    }
    pos = close + 1;
  }
  return rules;
}

}  // namespace shapeproc::io
