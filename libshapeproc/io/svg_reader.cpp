#include "libshapeproc/io/svg_reader.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <unordered_map>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/arc.hpp"
#include "libshapeproc/geometry/stroke_ink.hpp"
#include "libshapeproc/geometry/subpath_components.hpp"
#include "libshapeproc/geometry/visual_elements.hpp"
#include "libshapeproc/io/detail/svg_style_sheet.hpp"
#include "libshapeproc/io/svg_grammar.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

namespace {

using geometry::Affine2;
using geometry::Box2;
using geometry::Drawable2;
using geometry::FillRule;
using geometry::Path2;
using geometry::Scene;
using geometry::Segment2;
using geometry::Style;
using geometry::Vec2;

const std::set<std::string, std::less<>> kInheritedProperties = {"fill",
                                                                 "fill-opacity",
                                                                 "fill-rule",
                                                                 "stroke",
                                                                 "stroke-width",
                                                                 "stroke-opacity",
                                                                 "stroke-linecap",
                                                                 "stroke-linejoin",
                                                                 "stroke-miterlimit",
                                                                 "stroke-dasharray",
                                                                 "stroke-dashoffset",
                                                                 "color",
                                                                 "visibility"};
const std::set<std::string, std::less<>> kOwnProperties = {"opacity", "display", "vector-effect"};

const std::set<std::string, std::less<>> kNeverDrawn = {
    "defs",           "symbol", "clipPath",      "mask",  "pattern",   "marker",   "linearGradient",
    "radialGradient", "filter", "style",         "title", "desc",      "metadata", "script",
    "text",           "image",  "foreignObject", "font",  "font-face", "view",     "cursor"};
// Limits that keep a hostile file from exhausting the stack or the memory (docs/reliability.md):
// nesting of elements (the traversals below recurse), copies made by <use>, and path segments
// drawn in all, copies included. Real drawings stay far below them.
constexpr int kMaxNesting = 256;
constexpr std::size_t kMaxUseCopies = 100'000;
constexpr std::size_t kMaxSegments = 2'000'000;

// Coordinates beyond this after transforms are refused (as io/scene_io.cpp refuses them in any
// format), before the stroke outlines and regrouping would compute with infinities.
constexpr double kMaxCoordinate = 1e12;

bool within_range(const Drawable2& drawable) {
  const auto ok = [](const Vec2& p) {
    return p.allFinite() && p.cwiseAbs().maxCoeff() <= kMaxCoordinate;
  };
  for (const Path2& path : drawable.paths) {
    for (const Segment2& s : path.segments) {
      if (!ok(s.start) || !ok(s.control1) || !ok(s.control2) || !ok(s.end)) return false;
    }
  }
  return true;
}

const std::set<std::string, std::less<>> kGroups = {"g", "a", "switch"};
const std::set<std::string, std::less<>> kDrawables = {"path", "rect",     "circle", "ellipse",
                                                       "line", "polyline", "polygon"};

// Element name without an `svg:` prefix; names with other prefixes keep theirs (and are ignored).
std::string local_name(pugi::xml_node node) {
  std::string name = node.name();
  if (name.rfind("svg:", 0) == 0) name.erase(0, 4);
  return name;
}

// Attribute by its local name, whatever the prefix (`xlink:href` and `href`, `inkscape:label`).
pugi::xml_attribute attribute_by_local_name(pugi::xml_node node, std::string_view local) {
  for (pugi::xml_attribute a : node.attributes()) {
    std::string_view name = a.name();
    const std::size_t colon = name.find(':');
    if (colon != std::string_view::npos) name.remove_prefix(colon + 1);
    if (name == local) return a;
  }
  return {};
}

// What a node inherits and carries down the tree.
struct State {
  Affine2 transform = Affine2::Identity();
  Style style;                      // resolved inherited properties
  double opacity = 1.0;             // product of the group opacities above
  std::string layer;                // label of the enclosing layer
  bool non_scaling_stroke = false;  // this node's vector-effect (not inherited)
};

class SvgReader {
 public:
  SvgReader(std::string_view text, std::string file, const ReaderOptions& options)
      : text_(text), file_(std::move(file)), options_(options) {}

  Scene read();

 private:
  [[noreturn]] void fail(pugi::xml_node node, const std::string& message) const {
    throw core::InputError(file_, line_of(node), message);
  }
  int line_at(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    const auto end = text_.begin() + std::min<std::ptrdiff_t>(offset, text_.size());
    return 1 + static_cast<int>(std::count(text_.begin(), end, '\n'));
  }
  int line_of(pugi::xml_node node) const { return node ? line_at(node.offset_debug()) : 0; }

  double length(pugi::xml_node node, const char* name, double fallback) const;
  std::optional<State> enter(pugi::xml_node node, const State& parent) const;
  void walk_container(pugi::xml_node node, const State& state);
  void make_element(pugi::xml_node node, const State& state);
  // An element at `position` with the scene's point shape (added on first use).
  void add_point(const geometry::Vec3& position, int category);
  void collect(pugi::xml_node node, const State& state, std::vector<Drawable2>& parts,
               int use_depth) const;
  std::vector<Path2> drawable_paths(pugi::xml_node node, const std::string& name) const;
  Drawable2 styled(std::vector<Path2> paths, const State& state) const;
  // The drawable as its visible ink: its fill, and its stroke as a filled outline of the
  // stroke's width, caps and joins (geometry/stroke_ink.hpp).
  void append_visible_ink(Drawable2 drawable, std::vector<Drawable2>& parts) const;
  std::string category_of(pugi::xml_node node, const State& state,
                          const std::vector<Drawable2>& parts) const;
  bool is_layer(pugi::xml_node node) const {
    return std::string_view(attribute_by_local_name(node, "groupmode").value()) == "layer";
  }
  bool is_window(pugi::xml_node node) const {
    return local_name(node) == "rect" && std::string_view(node.attribute("id").value()) == "window";
  }
  void set_window_from_root(pugi::xml_node root);
  // Whether a non-layer group holds drawables (then elements are groups unless asked otherwise).
  bool has_element_groups(pugi::xml_node node) const;
  // The elements regrouped as connected pieces of ink (visual), or joined across the tile.
  void regroup_as_seen();
  // Groups as elements that hold many separate pieces of ink get a note naming --elements visual.
  void note_groups_of_many_pieces();

  std::string_view text_;
  std::string file_;
  const ReaderOptions& options_;
  ElementRule rule_ = ElementRule::groups;  // options_.elements, decided for this file
  pugi::xml_document document_;
  std::unordered_map<std::string, pugi::xml_node> ids_;
  StyleSheet css_;
  std::optional<Box2> window_rect_;
  pugi::xml_node window_node_;
  Scene scene_;
  mutable std::vector<geometry::Style> drawn_styles_;  // of the element being collected, as drawn
  mutable std::size_t use_copies_ = 0, segments_ = 0;  // drawn so far, against the limits
};

double SvgReader::length(pugi::xml_node node, const char* name, double fallback) const {
  const pugi::xml_attribute a = node.attribute(name);
  if (!a) return fallback;
  std::string_view text = trim(a.value());
  static const std::pair<const char*, double> kUnits[] = {{"px", 1.0},         {"pt", 96.0 / 72.0},
                                                          {"pc", 16.0},        {"mm", 96.0 / 25.4},
                                                          {"cm", 96.0 / 2.54}, {"in", 96.0}};
  double scale = 1.0;
  for (const auto& [unit, factor] : kUnits) {
    const std::string_view u(unit);
    if (text.size() > u.size() && text.substr(text.size() - u.size()) == u) {
      text.remove_suffix(u.size());
      scale = factor;
      break;
    }
  }
  const auto value = parse_number(text);
  if (!value) {
    fail(node, "<" + local_name(node) + "> attribute " + name +
                   ": expected a finite length, got '" + a.value() + "'");
  }
  return *value * scale;
}

std::optional<State> SvgReader::enter(pugi::xml_node node, const State& parent) const {
  State state = parent;
  Declarations declarations;
  auto accept = [](const std::string& property) {
    return kInheritedProperties.count(property) > 0 || kOwnProperties.count(property) > 0;
  };
  for (pugi::xml_attribute a : node.attributes()) {
    if (accept(a.name())) declarations.emplace_back(a.name(), std::string(trim(a.value())));
  }
  // Style sheet rules by specificity, then document order.
  const std::string tag = local_name(node);
  const std::vector<const CssRule*> matching =
      css_.empty()
          ? std::vector<const CssRule*>()
          : css_.matching(tag, node.attribute("id").value(), node.attribute("class").value());
  for (const CssRule* rule : matching) {
    for (const auto& d : rule->declarations) {
      if (accept(d.first)) declarations.push_back(d);
    }
  }
  for (const auto& d : parse_declarations(node.attribute("style").value())) {
    if (accept(d.first)) declarations.push_back(d);
  }

  state.non_scaling_stroke = false;
  for (const auto& [name, value] : declarations) {
    if (value == "inherit") continue;
    if (name == "vector-effect") {
      state.non_scaling_stroke = value == "non-scaling-stroke";
      continue;
    }
    if (name == "display") {
      if (value == "none") return std::nullopt;
      continue;
    }
    if (name == "opacity") {
      const auto alpha = parse_number(value);
      if (!alpha) fail(node, "opacity: expected a number, got '" + value + "'");
      state.opacity *= std::clamp(*alpha, 0.0, 1.0);
      continue;
    }
    state.style[name] = value;
  }
  // A nested <svg> establishes a viewport at (x, y); its viewBox scaling is not applied.
  if (tag == "svg" && node != document_.document_element()) {
    state.transform =
        state.transform * Eigen::Translation2d(length(node, "x", 0), length(node, "y", 0));
  }
  if (const pugi::xml_attribute t = node.attribute("transform")) {
    try {
      state.transform = state.transform * svg::parse_transform(t.value());
    } catch (const svg::GrammarError& e) {
      fail(node, "<" + tag + "> transform: " + e.what() + " '" + t.value() + "'");
    }
  }
  return state;
}

Scene SvgReader::read() {
  if (trim(text_).empty()) throw core::InputError(file_, 0, "the file is empty");
  const pugi::xml_parse_result parsed = document_.load_buffer(
      text_.data(), text_.size(), pugi::parse_default | pugi::parse_ws_pcdata_single);
  if (!parsed) {
    throw core::InputError(file_, line_at(parsed.offset),
                           std::string("malformed XML: ") + parsed.description());
  }
  const pugi::xml_node root = document_.document_element();
  if (local_name(root) != "svg") {
    fail(root, "the root element is <" + std::string(root.name()) + ">, not <svg>");
  }
  int order = 0;
  // Index ids and style sheets.
  struct Indexer : pugi::xml_tree_walker {
    SvgReader* reader;
    int* order;
    pugi::xml_node too_deep;
    bool for_each(pugi::xml_node& node) override {
      if (node.type() != pugi::node_element) return true;
      if (depth() >= kMaxNesting) {
        too_deep = node;
        return false;
      }
      if (const char* id = node.attribute("id").value(); *id) reader->ids_.emplace(id, node);
      if (local_name(node) == "style") {
        reader->css_.add(parse_style_sheet(node.child_value(), *order));
      }
      if (reader->is_window(node) && !reader->window_node_) reader->window_node_ = node;
      return true;
    }
  } indexer;
  indexer.reader = this;
  indexer.order = &order;
  document_.traverse(indexer);
  if (indexer.too_deep) {
    fail(indexer.too_deep,
         "elements nest more than " + std::to_string(kMaxNesting) + " levels deep, the most read");
  }

  const std::optional<State> root_state = enter(root, State());
  scene_.dimension = 2;
  rule_ = options_.split_subpaths ? ElementRule::subpaths : options_.elements;
  if (rule_ == ElementRule::automatic) {
    // The project's own outputs name their elements: each drawable or group is one.
    const bool written_here =
        root.find_child_by_attribute("id", "shapeproc") || root.find_node([](pugi::xml_node n) {
          return static_cast<bool>(n.attribute("data-category"));
        });
    rule_ = written_here || has_element_groups(root) ? ElementRule::groups : ElementRule::visual;
  }
  if (root_state) walk_container(root, *root_state);
  set_window_from_root(root);
  if (scene_.elements.empty()) {
    if (options_.empty_outputs && root.find_child_by_attribute("id", "shapeproc"))
      return std::move(scene_);
    throw core::InputError(file_, 0,
                           "no elements found (nothing drawable outside <defs> and hidden parts)");
  }
  if (rule_ == ElementRule::visual || options_.tile) {
    regroup_as_seen();
  } else if (rule_ == ElementRule::groups) {
    note_groups_of_many_pieces();
  }
  return std::move(scene_);
}

bool SvgReader::has_element_groups(pugi::xml_node node) const {
  if (options_.groups == GroupMode::container) return false;
  std::vector<pugi::xml_node> drawn;  // children that draw: drawables, groups, nested svg
  for (pugi::xml_node child : node.children()) {
    if (child.type() != pugi::node_element) continue;
    const std::string name = local_name(child);
    if (kNeverDrawn.count(name) || name.find(':') != std::string::npos || is_window(child))
      continue;
    if (kGroups.count(name) || name == "svg" || kDrawables.count(name) || name == "use")
      drawn.push_back(child);
  }
  // A group holding everything is a wrapper that carries style (fill, transform), not an element.
  if (drawn.size() == 1 && kGroups.count(local_name(drawn.front())))
    return has_element_groups(drawn.front());
  for (pugi::xml_node child : drawn) {
    const std::string name = local_name(child);
    if (kGroups.count(name) && !is_layer(child)) return true;
    if ((kGroups.count(name) || name == "svg") && has_element_groups(child)) return true;
  }
  return false;
}

void SvgReader::note_groups_of_many_pieces() {
  std::size_t pieces = 0;
  for (const geometry::Shape& shape : scene_.shapes) {
    if (const auto* planar = std::get_if<geometry::PlanarShape>(&shape.geometry)) {
      for (const Drawable2& part : planar->parts)
        pieces += geometry::split_disjoint_subpaths(part).size();
    }
  }
  const std::size_t elements = scene_.elements.size();
  if (pieces >= 8 && pieces >= 4 * elements) {
    scene_.notes.push_back(std::to_string(elements) + " groups hold " + std::to_string(pieces) +
                           " separate pieces of ink: if those are the drawing's elements, try "
                           "elements=visual");
  }
}

void SvgReader::regroup_as_seen() {
  geometry::VisualOptions visual;
  visual.nested_separate = options_.nested_separate;
  visual.tile = options_.tile;
  visual.keep_elements = rule_ != ElementRule::visual;
  const std::size_t drawn = scene_.elements.size();  // visual: a drawable each
  geometry::VisualElements regrouped = geometry::visual_elements(scene_, visual);
  if (regrouped.scene.elements.empty()) {
    throw core::InputError(file_, 0, "no ink inside the tile");
  }
  regrouped.scene.notes = std::move(regrouped.notes);
  const std::size_t subpaths = regrouped.subpaths, elements = regrouped.scene.elements.size();
  if (rule_ == ElementRule::visual && subpaths >= 8 && elements * 8 <= subpaths) {
    regrouped.scene.notes.push_back(
        std::to_string(subpaths) + " subpaths formed " + std::to_string(elements) +
        " elements as seen: if the drawing's elements are smaller, try nested_separate or "
        "elements=subpaths");
  }
  // A file of a few paths that read as seen makes a few elements more or fewer: likely one path
  // per element, with pieces of ink the reader sees apart (or joined).
  if (rule_ == ElementRule::visual && drawn >= 4 && elements != drawn && 2 * elements >= drawn &&
      elements <= 2 * drawn) {
    regrouped.scene.notes.push_back("the file draws " + std::to_string(drawn) +
                                    " shapes, read as seen they make " + std::to_string(elements) +
                                    " elements: if each shape is one element, try elements=paths");
  }
  scene_ = std::move(regrouped.scene);
}

void SvgReader::set_window_from_root(pugi::xml_node root) {
  std::string_view width_text = trim(root.attribute("width").value());
  if (window_node_) {
    if (!window_rect_) {
      fail(window_node_, "<rect id=\"window\"> is hidden or has no size");
    }
    scene_.window = geometry::lift(*window_rect_);
  } else if (const pugi::xml_attribute view_box = root.attribute("viewBox")) {
    const auto values = parse_number_list(view_box.value());
    if (!values || values->size() != 4) {
      fail(root, std::string("viewBox: expected four numbers, got '") + view_box.value() + "'");
    }
    const auto& v = *values;
    scene_.window =
        geometry::Box3(geometry::Vec3(v[0], v[1], 0), geometry::Vec3(v[0] + v[2], v[1] + v[3], 0));
    // Units follow the width when it maps one unit of the viewBox to one unit of length.
    for (const char* unit : {"mm", "cm", "in", "pt", "pc"}) {
      const std::string_view u(unit);
      if (width_text.size() > u.size() && width_text.substr(width_text.size() - u.size()) == u) {
        const auto w = parse_number(width_text.substr(0, width_text.size() - u.size()));
        if (w && *w == v[2]) scene_.units = unit;
      }
    }
  } else if (root.attribute("width") && root.attribute("height")) {
    scene_.window =
        geometry::Box3(geometry::Vec3::Zero(),
                       geometry::Vec3(length(root, "width", 0), length(root, "height", 0), 0));
  } else {
    fail(root,
         "no window: give the root a viewBox or width and height, or add <rect id=\"window\">");
  }
  const geometry::Vec3 sizes = scene_.window.sizes();
  if (!(sizes.x() > 0.0 && sizes.y() > 0.0)) {
    fail(window_node_ ? window_node_ : root, "the window has zero size");
  }
}

void SvgReader::walk_container(pugi::xml_node node, const State& state) {
  for (pugi::xml_node child : node.children()) {
    if (child.type() != pugi::node_element) continue;
    const std::string name = local_name(child);
    if (kNeverDrawn.count(name) || name.find(':') != std::string::npos) continue;
    const std::optional<State> child_state = enter(child, state);
    if (!child_state) continue;
    if (is_window(child)) {
      if (child == window_node_) {
        const double x = length(child, "x", 0), y = length(child, "y", 0);
        const double w = length(child, "width", 0), h = length(child, "height", 0);
        Box2 box;
        for (const Vec2& corner :
             {Vec2(x, y), Vec2(x + w, y), Vec2(x, y + h), Vec2(x + w, y + h)}) {
          box.extend(child_state->transform * corner);
        }
        window_rect_ = box;
      }
      continue;
    }
    if (kGroups.count(name)) {
      if (is_layer(child) || options_.groups == GroupMode::container ||
          rule_ == ElementRule::visual || rule_ == ElementRule::paths) {
        State inside = *child_state;
        if (is_layer(child)) {
          const pugi::xml_attribute label = attribute_by_local_name(child, "label");
          inside.layer = label ? label.value() : child.attribute("id").value();
        }
        walk_container(child, inside);
      } else {
        make_element(child, *child_state);
      }
    } else if (name == "svg") {
      walk_container(child, *child_state);
    } else if (kDrawables.count(name) || name == "use") {
      make_element(child, *child_state);
    }
  }
}

void SvgReader::add_point(const geometry::Vec3& position, int category) {
  int shape = -1;
  for (std::size_t s = 0; s < scene_.shapes.size() && shape < 0; ++s)
    if (std::holds_alternative<geometry::PointShape>(scene_.shapes[s].geometry))
      shape = static_cast<int>(s);
  if (shape < 0) {
    shape = static_cast<int>(scene_.shapes.size());
    scene_.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  }
  geometry::Element element;
  element.shape = shape;
  element.category = category;
  element.position = position;
  scene_.elements.push_back(element);
}

void SvgReader::make_element(pugi::xml_node node, const State& state) {
  std::vector<Drawable2> parts;
  drawn_styles_.clear();
  collect(node, state, parts, 0);
  if (parts.empty()) return;
  const int category = scene_.category_index(category_of(node, state, parts));
  const std::string id = node.attribute("id").value();
  if (node.attribute("data-point")) {  // a point of the project's own output: its dot's centre
    add_point(geometry::bounding_box(geometry::Shape{geometry::PlanarShape{parts}, id}).center(),
              category);
    return;
  }
  if (rule_ == ElementRule::subpaths && kDrawables.count(local_name(node))) {
    for (const Drawable2& part : parts) {
      for (Drawable2& piece : geometry::split_disjoint_subpaths(part)) {
        geometry::Shape shape{geometry::PlanarShape{{std::move(piece)}}, id};
        geometry::add_element(scene_, std::move(shape), category);
      }
    }
    return;
  }
  geometry::Shape shape{geometry::PlanarShape{std::move(parts)}, id};
  geometry::add_element(scene_, std::move(shape), category);
}

void SvgReader::collect(pugi::xml_node node, const State& state, std::vector<Drawable2>& parts,
                        int use_depth) const {
  const std::string name = local_name(node);
  if (kGroups.count(name) || name == "svg" || name == "symbol") {
    for (pugi::xml_node child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string child_name = local_name(child);
      if (kNeverDrawn.count(child_name) || child_name.find(':') != std::string::npos) continue;
      if (const std::optional<State> child_state = enter(child, state)) {
        collect(child, *child_state, parts, use_depth);
      }
    }
  } else if (name == "use") {
    const pugi::xml_attribute href = attribute_by_local_name(node, "href");
    const std::string_view target_ref = trim(href.value());
    if (target_ref.size() < 2 || target_ref.front() != '#') {
      fail(node, "<use> needs href=\"#id\" pointing into this file");
    }
    const auto target = ids_.find(std::string(target_ref.substr(1)));
    if (target == ids_.end())
      fail(node, "<use> refers to unknown id '" + std::string(target_ref) + "'");
    if (use_depth >= 32) fail(node, "<use> references nest too deep (a cycle?)");
    if (++use_copies_ > kMaxUseCopies) {
      fail(node, "<use> makes more than " + std::to_string(kMaxUseCopies) +
                     " copies in all, the most read");
    }
    State placed = state;
    placed.transform =
        placed.transform * Eigen::Translation2d(length(node, "x", 0), length(node, "y", 0));
    if (const std::optional<State> target_state = enter(target->second, placed)) {
      collect(target->second, *target_state, parts, use_depth + 1);
    }
  } else if (kDrawables.count(name)) {
    const auto visibility = state.style.find("visibility");
    if (visibility != state.style.end() && visibility->second != "visible" &&
        visibility->second != "inherit") {
      return;
    }
    std::vector<Path2> paths = drawable_paths(node, name);
    for (const Path2& path : paths) segments_ += path.segments.size();
    if (segments_ > kMaxSegments) {
      fail(node, "the drawing holds more than " + std::to_string(kMaxSegments) +
                     " path segments (<use> copies included), the most read");
    }
    if (paths.empty()) return;
    Drawable2 drawable = styled(std::move(paths), state);
    if (!within_range(drawable)) {
      fail(node, "<" + name + "> has coordinates beyond ±1e12 or not finite after transforms");
    }
    append_visible_ink(std::move(drawable), parts);
  }
}

std::vector<Path2> SvgReader::drawable_paths(pugi::xml_node node, const std::string& name) const {
  std::vector<Path2> paths;
  auto positive = [&](const char* attribute, double value) {
    if (value < 0) fail(node, "<" + name + "> " + attribute + " must not be negative");
    return value > 0;
  };
  if (name == "path") {
    const char* data = node.attribute("d").value();
    try {
      paths = svg::parse_path_data(data, kMaxSegments - std::min(segments_, kMaxSegments));
    } catch (const svg::GrammarError& e) {
      std::string shown = data;
      if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
      fail(node, std::string("<path> d: ") + e.what() + " in '" + shown + "'");
    }
  } else if (name == "rect") {
    const double x = length(node, "x", 0), y = length(node, "y", 0);
    const double w = length(node, "width", 0), h = length(node, "height", 0);
    if (!positive("width", w) || !positive("height", h)) return paths;
    double rx = length(node, "rx", -1), ry = length(node, "ry", -1);
    if (rx < 0 && ry < 0) rx = ry = 0;
    if (rx < 0) rx = ry;
    if (ry < 0) ry = rx;
    rx = std::min(rx, w / 2);
    ry = std::min(ry, h / 2);
    Path2 path;
    path.closed = true;
    if (rx == 0 || ry == 0) {
      const Vec2 corners[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
      for (int i = 0; i < 4; ++i)
        path.segments.push_back(Segment2::line(corners[i], corners[(i + 1) % 4]));
    } else {
      auto line = [&](Vec2 a, Vec2 b) {
        if (a != b) path.segments.push_back(Segment2::line(a, b));
      };
      auto arc = [&](Vec2 a, Vec2 b) {
        geometry::append_elliptical_arc(path, a, rx, ry, 0, false, true, b);
      };
      line({x + rx, y}, {x + w - rx, y});
      arc({x + w - rx, y}, {x + w, y + ry});
      line({x + w, y + ry}, {x + w, y + h - ry});
      arc({x + w, y + h - ry}, {x + w - rx, y + h});
      line({x + w - rx, y + h}, {x + rx, y + h});
      arc({x + rx, y + h}, {x, y + h - ry});
      line({x, y + h - ry}, {x, y + ry});
      arc({x, y + ry}, {x + rx, y});
    }
    paths.push_back(std::move(path));
  } else if (name == "circle" || name == "ellipse") {
    const Vec2 centre(length(node, "cx", 0), length(node, "cy", 0));
    double rx, ry;
    if (name == "circle") {
      rx = ry = length(node, "r", 0);
      if (!positive("r", rx)) return paths;
    } else {
      rx = length(node, "rx", 0);
      ry = length(node, "ry", 0);
      if (!positive("rx", rx) || !positive("ry", ry)) return paths;
    }
    paths.push_back(geometry::ellipse_path(centre, rx, ry));
  } else if (name == "line") {
    const Vec2 a(length(node, "x1", 0), length(node, "y1", 0));
    const Vec2 b(length(node, "x2", 0), length(node, "y2", 0));
    Path2 path;
    path.segments.push_back(Segment2::line(a, b));
    paths.push_back(std::move(path));
  } else if (name == "polyline" || name == "polygon") {
    const char* text = node.attribute("points").value();
    const auto values = parse_number_list(text);
    if (!values) fail(node, "<" + name + "> points: expected finite numbers, got '" + text + "'");
    if (values->size() % 2 != 0) fail(node, "<" + name + "> points: odd number of coordinates");
    Path2 path;
    for (std::size_t i = 2; i + 1 < values->size(); i += 2) {
      path.segments.push_back(
          Segment2::line({(*values)[i - 2], (*values)[i - 1]}, {(*values)[i], (*values)[i + 1]}));
    }
    if (path.segments.empty()) return paths;
    if (name == "polygon") {
      if (path.segments.back().end != path.segments.front().start) {
        path.segments.push_back(
            Segment2::line(path.segments.back().end, path.segments.front().start));
      }
      path.closed = true;
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

void SvgReader::append_visible_ink(Drawable2 drawable, std::vector<Drawable2>& parts) const {
  drawn_styles_.push_back(drawable.style);
  if (!geometry::stroked(drawable)) {
    parts.push_back(std::move(drawable));
    return;
  }
  Box2 box;
  for (const Path2& path : drawable.paths) box.extend(geometry::bounding_box(path));
  const double size = box.isEmpty() ? 0.0 : box.diagonal().norm();
  std::optional<Drawable2> ink = geometry::stroke_ink(drawable, std::max(1e-3 * size, 1e-9));
  if (drawable.filled()) {
    drawable.style["stroke"] = "none";
    parts.push_back(std::move(drawable));
  } else if (!ink) {
    parts.push_back(std::move(drawable));  // a stroke that paints nothing stays a curve
  }
  if (ink) parts.push_back(std::move(*ink));
}

Drawable2 SvgReader::styled(std::vector<Path2> paths, const State& state) const {
  Drawable2 drawable;
  const Affine2& map = state.transform;
  if (!map.matrix().isIdentity(0.0)) {
    for (Path2& path : paths) geometry::transform(path, map);
  }
  drawable.paths = std::move(paths);
  Style style = state.style;
  const auto rule = style.find("fill-rule");
  if (rule != style.end()) {
    drawable.fill_rule = rule->second == "evenodd" ? FillRule::evenodd : FillRule::nonzero;
    style.erase(rule);
  }
  const std::string color = style.count("color") ? style.at("color") : "black";
  for (const char* paint : {"fill", "stroke"}) {
    auto it = style.find(paint);
    if (it != style.end() && to_lower(it->second) == "currentcolor") it->second = color;
  }
  style.erase("color");
  style.erase("visibility");
  // vector-effect: non-scaling-stroke keeps the width in the root's user space.
  if (auto width = style.find("stroke-width"); width != style.end() && !state.non_scaling_stroke) {
    const double scale = std::sqrt(std::abs(map.linear().determinant()));
    if (const auto w = parse_number(width->second); w && scale != 1.0) {
      width->second = core::format_number(*w * scale);
    }
  }
  if (state.opacity != 1.0) style["opacity"] = core::format_number(state.opacity);
  drawable.style = std::move(style);
  return drawable;
}

std::string SvgReader::category_of(pugi::xml_node node, const State& state,
                                   const std::vector<Drawable2>& parts) const {
  using Kind = CategoryRule::Kind;
  const CategoryRule& rule = options_.category_by;
  auto paint = [&](const char* property, const char* fallback) {
    // As drawn: the first drawable's own style, before its stroke became a part of its own.
    const Style& style = drawn_styles_.empty() ? parts.front().style : drawn_styles_.front();
    const auto it = style.find(property);
    const std::string value = it == style.end() ? fallback : it->second;
    return svg::normalise_color(value).value_or(to_lower(value));
  };
  switch (rule.kind) {
    case Kind::none:
      // The project's own outputs name each element's category: read back, they keep it.
      for (pugi::xml_node n = node; n; n = n.parent())
        if (const pugi::xml_attribute a = n.attribute("data-category")) return a.value();
      return "default";
    case Kind::fill:
      return paint("fill", "black");
    case Kind::stroke:
      return paint("stroke", "none");
    case Kind::class_name: {
      const std::string value(trim(node.attribute("class").value()));
      return value.empty() ? "none" : value;
    }
    case Kind::layer:
      return state.layer.empty() ? "none" : state.layer;
    case Kind::attribute:
      for (pugi::xml_node n = node; n; n = n.parent()) {
        if (const pugi::xml_attribute a = n.attribute(rule.attribute.c_str())) return a.value();
      }
      return "none";
  }
  return "default";
}

}  // namespace

Scene parse_svg(std::string_view text, const std::string& file_name, const ReaderOptions& options) {
  return SvgReader(text, file_name, options).read();
}

Scene read_svg(const std::filesystem::path& file, const ReaderOptions& options) {
  const std::string text = read_text_file(file);
  return parse_svg(text, file.string(), options);
}

}  // namespace shapeproc::io
