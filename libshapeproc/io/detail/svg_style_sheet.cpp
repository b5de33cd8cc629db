#include "libshapeproc/io/detail/svg_style_sheet.hpp"

#include <algorithm>
#include <tuple>

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
  for (std::size_t start = 0; (start = text.find("/*", start)) != std::string::npos;) {
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

void StyleSheet::add(std::vector<CssRule> rules) {
  for (CssRule& rule : rules) {
    const std::size_t index = rules_.size();
    if (!rule.id.empty()) {
      by_id_[rule.id].push_back(index);
    } else if (!rule.class_name.empty()) {
      by_class_[rule.class_name].push_back(index);
    } else {
      others_.push_back(index);
    }
    rules_.push_back(std::move(rule));
  }
}

std::vector<const CssRule*> StyleSheet::matching(std::string_view tag, std::string_view id,
                                                 std::string_view classes) const {
  std::vector<std::size_t> candidates = others_;
  const auto add = [&](const std::unordered_map<std::string, std::vector<std::size_t>>& map,
                       std::string_view key) {
    if (key.empty()) return;
    const auto it = map.find(std::string(key));
    if (it != map.end()) candidates.insert(candidates.end(), it->second.begin(), it->second.end());
  };
  add(by_id_, id);
  for (const std::string& name : split(classes, ' ')) add(by_class_, name);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<const CssRule*> out;
  for (const std::size_t index : candidates) {
    const CssRule& rule = rules_[index];
    if (rule.tag.empty() || rule.tag == tag || !rule.id.empty()) out.push_back(&rule);
  }
  std::stable_sort(out.begin(), out.end(), [](const CssRule* a, const CssRule* b) {
    return std::tie(a->specificity, a->order) < std::tie(b->specificity, b->order);
  });
  return out;
}

}  // namespace shapeproc::io
