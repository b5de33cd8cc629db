// Pictures through Cairo: scenes rasterised (domain masks) and rendered to PNG.
// Cairo is included by raster.cpp only.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "libshapeproc/geometry/raster.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/render/png_text.hpp"

namespace shapeproc::render {

// The filled shapes of a 2D scene (each element's shape placed, by its fill rule) drawn white on
// black over `box`, at width x height pixels, antialiased.
geometry::Raster rasterize_filled(const geometry::Scene& scene, const geometry::Box3& box,
                                  int width, int height);

struct RenderOptions {
  int long_side = 800;  // pixels along the longer side of the window
  double scale = 0.0;   // pixels per unit length; when positive, replaces long_side
  std::vector<bool>
      highlight;            // per element: draw in red with a red ring (collisions); may be empty
  bool draw_window = true;  // the window's outline, in grey
  PngText text;             // tEXt chunks (seed, command); none when empty
};

// Renders a scene to a PNG, written atomically: 2D with each drawable's style (fill, stroke,
// opacity), 3D as an orthographic view along −z with a painter's algorithm and flat shading.
void write_png(const geometry::Scene& scene, const std::filesystem::path& path,
               const RenderOptions& options = {});

// One picture of a contact sheet: a title above the scene, caption lines below it (wrapped to its
// width; a caption starting "fails" is drawn in red with the lines after it).
struct SheetPanel {
  const geometry::Scene* scene = nullptr;
  std::string title;
  std::vector<std::string> caption;
  RenderOptions options;  // its scale is replaced by the sheet's
};

// Several scenes side by side at one scale (pixels per unit length), in one PNG written
// atomically: `compare`'s overview picture.
void write_contact_sheet(const std::vector<SheetPanel>& panels, double scale,
                         const std::filesystem::path& path);

}  // namespace shapeproc::render
