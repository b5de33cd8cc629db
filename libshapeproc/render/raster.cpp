#include "libshapeproc/render/raster.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/render/png_text.hpp"

namespace shapeproc::render {

using geometry::Box3;
using geometry::Raster;
using geometry::Scene;
using geometry::Vec2;
using geometry::Vec3;

namespace {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

struct Colour {
  double r = 0, g = 0, b = 0;
};

// SVG colour values: #rgb, #rrggbb, rgb(r, g, b) and the common names; nullopt for none.
std::optional<Colour> parse_colour(const std::string& text) {
  static const std::map<std::string, Colour> names = {
      {"black", {0, 0, 0}},      {"white", {1, 1, 1}},       {"red", {1, 0, 0}},
      {"green", {0, 0.5, 0}},    {"blue", {0, 0, 1}},        {"yellow", {1, 1, 0}},
      {"gray", {0.5, 0.5, 0.5}}, {"grey", {0.5, 0.5, 0.5}},  {"orange", {1, 0.65, 0}},
      {"purple", {0.5, 0, 0.5}}, {"currentcolor", {0, 0, 0}}};
  std::string s;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)))
      s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s.empty() || s == "none" || s == "transparent") return std::nullopt;
  if (s[0] == '#') {
    unsigned v = 0;
    if (s.size() == 4 && std::sscanf(s.c_str() + 1, "%x", &v) == 1) {
      return Colour{((v >> 8) & 0xF) / 15.0, ((v >> 4) & 0xF) / 15.0, (v & 0xF) / 15.0};
    }
    if (s.size() == 7 && std::sscanf(s.c_str() + 1, "%x", &v) == 1) {
      return Colour{((v >> 16) & 0xFF) / 255.0, ((v >> 8) & 0xFF) / 255.0, (v & 0xFF) / 255.0};
    }
    return Colour{};
  }
  double r = 0, g = 0, b = 0;
  if (std::sscanf(s.c_str(), "rgb(%lf,%lf,%lf)", &r, &g, &b) == 3)
    return Colour{r / 255, g / 255, b / 255};
  const auto named = names.find(s);
  return named != names.end() ? named->second : Colour{};
}

double number_or(const geometry::Style& style, const std::string& key, double fallback) {
  const auto it = style.find(key);
  if (it == style.end()) return fallback;
  try {
    return std::stod(it->second);
  } catch (...) {
    return fallback;
  }
}

void add_path(cairo_t* cr, const geometry::Path2& path, const Vec2& offset) {
  if (path.segments.empty()) return;
  const Vec2 p = path.segments.front().start + offset;
  cairo_move_to(cr, p.x(), p.y());
  for (const geometry::Segment2& s : path.segments) {
    if (s.cubic) {
      const Vec2 a = s.control1 + offset, b = s.control2 + offset, e = s.end + offset;
      cairo_curve_to(cr, a.x(), a.y(), b.x(), b.y(), e.x(), e.y());
    } else {
      const Vec2 e = s.end + offset;
      cairo_line_to(cr, e.x(), e.y());
    }
  }
  if (path.closed) cairo_close_path(cr);
}

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::ostream*>(closure);
  out->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  return *out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

// Maps scene coordinates of `box` onto a width x height surface.
void set_view(cairo_t* cr, const Box3& box, int width, int height) {
  const Vec3 size = box.sizes();
  cairo_scale(cr, width / std::max(1e-300, size.x()), height / std::max(1e-300, size.y()));
  cairo_translate(cr, -box.min().x(), -box.min().y());
}

void draw_2d(cairo_t* cr, const Scene& scene, const RenderOptions& options, double pixel) {
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const geometry::Element& e = scene.elements[i];
    const bool red = i < options.highlight.size() && options.highlight[i];
    const Vec2 offset = e.position.head<2>();
    const geometry::Shape& shape = scene.shapes.at(static_cast<std::size_t>(e.shape));
    if (std::holds_alternative<geometry::PointShape>(shape.geometry)) {
      cairo_arc(cr, offset.x(), offset.y(), 2.5 * pixel, 0, 2 * core::kPi);
      if (red)
        cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
      else
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_fill(cr);
      continue;
    }
    const auto* planar = std::get_if<geometry::PlanarShape>(&shape.geometry);
    if (!planar) continue;
    for (const geometry::Drawable2& d : planar->parts) {
      const double opacity = number_or(d.style, "opacity", 1.0);
      cairo_new_path(cr);
      for (const geometry::Path2& path : d.paths) add_path(cr, path, offset);
      const auto fill = d.style.count("fill") ? parse_colour(d.style.at("fill"))
                                              : std::optional<Colour>(Colour{});
      const auto stroke =
          d.style.count("stroke") ? parse_colour(d.style.at("stroke")) : std::nullopt;
      if (fill) {
        const Colour c = red ? Colour{0.85, 0.1, 0.1} : *fill;
        cairo_set_source_rgba(cr, c.r, c.g, c.b, opacity * number_or(d.style, "fill-opacity", 1.0));
        cairo_set_fill_rule(cr, d.fill_rule == geometry::FillRule::evenodd
                                    ? CAIRO_FILL_RULE_EVEN_ODD
                                    : CAIRO_FILL_RULE_WINDING);
        if (stroke)
          cairo_fill_preserve(cr);
        else
          cairo_fill(cr);
      }
      if (stroke) {
        const Colour c = red ? Colour{0.85, 0.1, 0.1} : *stroke;
        cairo_set_source_rgba(cr, c.r, c.g, c.b,
                              opacity * number_or(d.style, "stroke-opacity", 1.0));
        cairo_set_line_width(cr, std::max(pixel, number_or(d.style, "stroke-width", 1.0)));
        cairo_stroke(cr);
      }
      cairo_new_path(cr);
    }
  }
}

void draw_3d(cairo_t* cr, const Scene& scene, const RenderOptions& options, double pixel) {
  struct Face {
    std::array<Vec3, 3> p;
    double depth;
    bool red;
  };
  std::vector<Face> faces;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const geometry::Element& e = scene.elements[i];
    const auto* mesh = std::get_if<geometry::MeshShape>(
        &scene.shapes.at(static_cast<std::size_t>(e.shape)).geometry);
    if (!mesh) continue;
    const bool red = i < options.highlight.size() && options.highlight[i];
    for (const auto& t : mesh->mesh.triangles) {
      Face f;
      for (int k = 0; k < 3; ++k)
        f.p[static_cast<std::size_t>(k)] =
            mesh->mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])] +
            e.position;
      f.depth = (f.p[0].z() + f.p[1].z() + f.p[2].z()) / 3;
      f.red = red;
      faces.push_back(f);
    }
  }
  // Viewer on +z looking down: far (low z) faces first.
  std::stable_sort(faces.begin(), faces.end(),
                   [](const Face& a, const Face& b) { return a.depth < b.depth; });
  const Vec3 light = Vec3(-0.4, -0.5, 1.0).normalized();
  for (const Face& f : faces) {
    Vec3 normal = (f.p[1] - f.p[0]).cross(f.p[2] - f.p[0]);
    if (normal.norm() == 0) continue;
    normal.normalize();
    const double shade = 0.25 + 0.75 * std::abs(normal.dot(light));
    cairo_move_to(cr, f.p[0].x(), f.p[0].y());
    cairo_line_to(cr, f.p[1].x(), f.p[1].y());
    cairo_line_to(cr, f.p[2].x(), f.p[2].y());
    cairo_close_path(cr);
    if (f.red)
      cairo_set_source_rgb(cr, 0.9 * shade, 0.15 * shade, 0.15 * shade);
    else
      cairo_set_source_rgb(cr, 0.55 * shade, 0.65 * shade, 0.8 * shade);
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0, 0, 0, 0.15);
    cairo_set_line_width(cr, 0.3 * pixel);
    cairo_stroke(cr);
  }
}

}  // namespace

Raster rasterize_filled(const Scene& scene, const Box3& box, int width, int height) {
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_A8, width, height));
  Context cr(cairo_create(surface.get()));
  set_view(cr.get(), box, width, height);
  cairo_set_source_rgba(cr.get(), 0, 0, 0, 1);
  for (const geometry::Element& e : scene.elements) {
    const auto* planar = std::get_if<geometry::PlanarShape>(
        &scene.shapes.at(static_cast<std::size_t>(e.shape)).geometry);
    if (!planar) continue;
    for (const geometry::Drawable2& d : planar->parts) {
      if (!d.filled()) continue;
      cairo_new_path(cr.get());
      for (const geometry::Path2& path : d.paths) add_path(cr.get(), path, e.position.head<2>());
      cairo_set_fill_rule(cr.get(), d.fill_rule == geometry::FillRule::evenodd
                                        ? CAIRO_FILL_RULE_EVEN_ODD
                                        : CAIRO_FILL_RULE_WINDING);
      cairo_fill(cr.get());
    }
  }
  cairo_surface_flush(surface.get());
  Raster raster;
  raster.width = width;
  raster.height = height;
  raster.values.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  const int stride = cairo_image_surface_get_stride(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      raster.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x)] = static_cast<float>(data[y * stride + x] / 255.0);
  return raster;
}

namespace {

// What a scene's picture covers (its window, or its shapes' bounds without one) and its size in
// pixels.
struct View {
  Box3 box;
  double scale = 0.0;
  int width = 0, height = 0;
};

View view_of(const Scene& scene, const RenderOptions& options) {
  View v;
  v.box = scene.window;
  if (v.box.isEmpty()) {
    for (std::size_t i = 0; i < scene.elements.size(); ++i)
      v.box.extend(geometry::bounding_box(scene.placed_shape(i)));
  }
  const Vec3 size = v.box.sizes();
  const double longest = std::max(size.x(), size.y());
  if (!(longest > 0)) throw core::ArgumentError("render", "the scene has an empty window");
  v.scale = options.scale > 0 ? options.scale : options.long_side / longest;
  v.width = std::max(1, static_cast<int>(std::lround(v.scale * size.x())));
  v.height = std::max(1, static_cast<int>(std::lround(v.scale * size.y())));
  return v;
}

// Draws the scene over the view, whose top-left corner is the context's current origin.
void draw_scene(cairo_t* context, const Scene& scene, const RenderOptions& options,
                const View& view) {
  cairo_save(context);
  Context cr(cairo_reference(context));
  const Box3& box = view.box;
  const Vec3 size = box.sizes();
  cairo_rectangle(cr.get(), 0, 0, view.width, view.height);  // nothing drawn beyond the view
  cairo_clip(cr.get());
  set_view(cr.get(), box, view.width, view.height);
  const double pixel = 1.0 / view.scale;
  if (scene.dimension == 3)
    draw_3d(cr.get(), scene, options, pixel);
  else
    draw_2d(cr.get(), scene, options, pixel);
  // Highlighted elements also get a red ring, visible whatever their own colours.
  for (std::size_t i = 0; i < scene.elements.size() && i < options.highlight.size(); ++i) {
    if (!options.highlight[i]) continue;
    const geometry::Element& e = scene.elements[i];
    const Box3 shape_box =
        geometry::bounding_box(scene.shapes.at(static_cast<std::size_t>(e.shape)));
    const double radius = 0.5 * shape_box.sizes().head<2>().norm() + 4 * pixel;
    cairo_new_path(cr.get());
    cairo_arc(cr.get(), e.position.x(), e.position.y(), radius, 0, 2 * core::kPi);
    cairo_set_source_rgba(cr.get(), 0.85, 0.1, 0.1, 0.9);
    cairo_set_line_width(cr.get(), 2 * pixel);
    cairo_stroke(cr.get());
  }
  if (options.draw_window) {
    cairo_rectangle(cr.get(), box.min().x(), box.min().y(), size.x(), size.y());
    cairo_set_source_rgb(cr.get(), 0.6, 0.6, 0.6);
    cairo_set_line_width(cr.get(), 2 * pixel);
    cairo_stroke(cr.get());
  }
  cairo_restore(context);
}

std::string png_bytes(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  std::ostringstream bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface, write_to_stream, &bytes);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("render: ") + cairo_status_to_string(status));
  return bytes.str();
}

// Words of `text` broken into lines of at most about `characters`.
std::vector<std::string> wrap(const std::string& text, std::size_t characters) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string line;
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > characters) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

void write_png(const Scene& scene, const std::filesystem::path& path,
               const RenderOptions& options) {
  const View view = view_of(scene, options);
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, view.width, view.height));
  Context cr(cairo_create(surface.get()));
  cairo_set_source_rgb(cr.get(), 1, 1, 1);
  cairo_paint(cr.get());
  draw_scene(cr.get(), scene, options, view);
  const std::string bytes = png_bytes(surface.get());
  const std::string png = options.text.empty() ? bytes : add_png_text(bytes, options.text);
  core::write_file_atomically(path, [&](std::ostream& out) { out << png; });
}

void write_contact_sheet(const std::vector<SheetPanel>& panels, double scale,
                         const std::filesystem::path& path) {
  if (panels.empty()) throw core::ArgumentError("render", "a contact sheet needs a picture");
  constexpr int kMargin = 16, kTitle = 26, kLine = 17;
  std::vector<View> views;
  std::vector<std::vector<std::string>> captions;
  int width = kMargin, height = 0;
  for (const SheetPanel& p : panels) {
    RenderOptions options = p.options;
    options.scale = scale;
    views.push_back(view_of(*p.scene, options));
    std::vector<std::string> lines;
    for (const std::string& c : p.caption) {
      const auto more = wrap(c, static_cast<std::size_t>(std::max(24, views.back().width / 7)));
      lines.insert(lines.end(), more.begin(), more.end());
    }
    captions.push_back(lines);
    width += views.back().width + kMargin;
    height =
        std::max(height, kTitle + views.back().height + 6 + static_cast<int>(lines.size()) * kLine);
  }
  height += 2 * kMargin;
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  Context cr(cairo_create(surface.get()));
  cairo_set_source_rgb(cr.get(), 1, 1, 1);
  cairo_paint(cr.get());
  cairo_select_font_face(cr.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  int x = kMargin;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    cairo_set_source_rgb(cr.get(), 0.1, 0.1, 0.1);
    cairo_set_font_size(cr.get(), 17);
    cairo_move_to(cr.get(), x, kMargin + 17);
    cairo_show_text(cr.get(), panels[i].title.c_str());
    cairo_save(cr.get());
    cairo_translate(cr.get(), x, kMargin + kTitle);
    RenderOptions options = panels[i].options;
    options.scale = scale;
    draw_scene(cr.get(), *panels[i].scene, options, views[i]);
    cairo_restore(cr.get());
    cairo_set_font_size(cr.get(), 13);
    for (std::size_t l = 0; l < captions[i].size(); ++l) {
      const bool bad =
          captions[i][l].rfind("fails", 0) == 0 || (l > 0 && captions[i][0].rfind("fails", 0) == 0);
      if (bad)
        cairo_set_source_rgb(cr.get(), 0.75, 0.1, 0.1);
      else
        cairo_set_source_rgb(cr.get(), 0.25, 0.25, 0.25);
      cairo_move_to(cr.get(), x,
                    kMargin + kTitle + views[i].height + 6 + static_cast<int>(l + 1) * kLine - 4);
      cairo_show_text(cr.get(), captions[i][l].c_str());
    }
    x += views[i].width + kMargin;
  }
  const std::string png = png_bytes(surface.get());
  core::write_file_atomically(path, [&](std::ostream& out) { out << png; });
}
}  // namespace shapeproc::render
