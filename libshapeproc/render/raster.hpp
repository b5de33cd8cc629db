// Pictures through Cairo: grayscale PNG masks and intensity maps in, scenes rendered to PNG out.
// Cairo is included by raster.cpp only.
#pragma once

#include <filesystem>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::render {

// Grey levels in [0, 1], row-major, row 0 at the top (SVG's y axis points down, and so do
// scenes read from SVG).
struct Raster {
  int width = 0, height = 0;
  std::vector<float> values;

  float at(int x, int y) const { return values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
  // The value of the pixel holding `p`, with the raster stretched over `box` (x right, y down);
  // 0 outside the box.
  float sample(const geometry::Box3& box, const geometry::Vec2& p) const;
};

// Reads a PNG as luminance times alpha (transparent counts as black). Throws io::InputError
// naming the file when it cannot be read or is not a PNG.
Raster read_grayscale_png(const std::filesystem::path& path);

// The filled shapes of a 2D scene (each element's shape placed, by its fill rule) drawn white on
// black over `box`, at width x height pixels, antialiased.
Raster rasterize_filled(const geometry::Scene& scene, const geometry::Box3& box, int width, int height);

struct RenderOptions {
  int long_side = 800;                // pixels along the longer side of the window
  double scale = 0.0;                 // pixels per unit length; when positive, replaces long_side
  std::vector<bool> highlight;        // per element: draw in red with a red ring (collisions); may be empty
  bool draw_window = true;            // the window's outline, in grey
};

// Renders a scene to a PNG, written atomically: 2D with each drawable's style (fill, stroke,
// opacity), 3D as an orthographic view along −z with a painter's algorithm and flat shading.
void write_png(const geometry::Scene& scene, const std::filesystem::path& path, const RenderOptions& options = {});

}  // namespace shapeproc::render
