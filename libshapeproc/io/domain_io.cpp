#include "libshapeproc/io/domain_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/render/raster.hpp"

namespace shapeproc::io {

std::optional<std::vector<double>> parse_size(std::string_view text, const geometry::Box3* window) {
  const std::vector<std::string> parts = split(text, ',');
  if (parts.size() < 2 || parts.size() > 3) return std::nullopt;
  std::vector<double> sizes;
  for (std::size_t axis = 0; axis < parts.size(); ++axis) {
    std::string_view part = trim(parts[axis]);
    double factor = 1.0;
    if (!part.empty() && std::toupper(static_cast<unsigned char>(part.back())) == "WHD"[axis]) {
      if (!window || window->isEmpty()) return std::nullopt;
      factor = window->sizes()[static_cast<Eigen::Index>(axis)];
      part.remove_suffix(1);
      part = trim(part);
      if (part.empty()) part = "1";
    }
    const std::optional<double> value = parse_number(part);
    if (!value) return std::nullopt;
    const double size = *value * factor;
    if (!(size > 0) || !std::isfinite(size)) return std::nullopt;
    sizes.push_back(size);
  }
  return sizes;
}

geometry::Raster read_domain_mask(const std::string& path) {
  const std::string extension = extension_of(path);
  if (extension == "png") return read_grayscale_png(path);
  if (extension != "svg")
    throw core::UsageError("{domain}: expected an .svg (filled shapes) or a .png mask, got '" +
                           path + "'");
  const geometry::Scene shapes = read_scene(path, {});
  if (shapes.dimension != 2 || shapes.elements.empty())
    throw core::InputError(path, 0, "the domain has no filled shape");
  const geometry::Vec3 size = shapes.window.sizes();
  const double longest = std::max(size.x(), size.y());
  const int width = std::max(8, static_cast<int>(std::lround(2048 * size.x() / longest)));
  const int height = std::max(8, static_cast<int>(std::lround(2048 * size.y() / longest)));
  geometry::Raster mask = render::rasterize_filled(shapes, shapes.window, width, height);
  if (std::none_of(mask.values.begin(), mask.values.end(), [](float v) { return v >= 0.5f; })) {
    throw core::InputError(path, 0, "the domain has no filled shape (nothing to sample in)");
  }
  return mask;
}

geometry::Domain read_domain(const DomainFiles& files, int dimension) {
  const auto& sizes = files.size;
  if (static_cast<int>(sizes.size()) != dimension ||
      !std::all_of(sizes.begin(), sizes.end(),
                   [](double v) { return v > 0 && std::isfinite(v); })) {
    std::string given;
    for (std::size_t i = 0; i < sizes.size(); ++i)
      given += (i ? "," : "") + core::format_number(sizes[i]);
    throw core::UsageError("{size}: expected " + std::string(dimension == 2 ? "W,H" : "W,H,D") +
                           " (positive) for a " + std::to_string(dimension) + "D model, got '" +
                           given + "'");
  }
  if (dimension != 2 && (!files.mask.empty() || !files.intensity.empty())) {
    throw core::UsageError("{domain} and {intensity} are for 2D models");
  }
  if (files.boundary == "torus" && !files.mask.empty()) {
    throw core::UsageError(
        "{boundary}=torus needs a rectangular domain: drop {domain} or use {boundary}=open");
  }
  const geometry::Boundary boundary =
      files.boundary.empty()
          ? (files.mask.empty() ? geometry::Boundary::torus : geometry::Boundary::open)
          : geometry::parse_boundary(files.boundary);
  geometry::Domain domain = geometry::Domain::from_sizes(sizes, boundary);
  if (!files.mask.empty())
    domain.set_mask(std::make_shared<const geometry::Raster>(read_domain_mask(files.mask)));
  if (!files.intensity.empty())
    domain.set_intensity(
        std::make_shared<const geometry::Raster>(read_grayscale_png(files.intensity)));
  return domain;
}

}  // namespace shapeproc::io
