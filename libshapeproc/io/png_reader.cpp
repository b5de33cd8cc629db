#include "libshapeproc/io/png_reader.hpp"

#include <cairo.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::io {

using geometry::Raster;

namespace {
struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
}  // namespace

Raster read_grayscale_png(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw core::InputError(path.string(), 0, "no such file");
  Surface surface(cairo_image_surface_create_from_png(path.string().c_str()));
  const cairo_status_t status = cairo_surface_status(surface.get());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw core::InputError(
        path.string(), 0,
        std::string("not a readable PNG image (") + cairo_status_to_string(status) + ")");
  }
  cairo_surface_flush(surface.get());
  Raster raster;
  raster.width = cairo_image_surface_get_width(surface.get());
  raster.height = cairo_image_surface_get_height(surface.get());
  if (raster.width <= 0 || raster.height <= 0)
    throw core::InputError(path.string(), 0, "the image is empty");
  const cairo_format_t format = cairo_image_surface_get_format(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  raster.values.resize(static_cast<std::size_t>(raster.width) *
                       static_cast<std::size_t>(raster.height));
  for (int y = 0; y < raster.height; ++y) {
    for (int x = 0; x < raster.width; ++x) {
      double value = 0.0;
      if (format == CAIRO_FORMAT_ARGB32 || format == CAIRO_FORMAT_RGB24) {
        std::uint32_t pixel;
        std::memcpy(&pixel, data + y * stride + 4 * x, 4);
        // Cairo stores colour premultiplied by alpha: this is luminance × alpha.
        value = (0.2126 * ((pixel >> 16) & 0xFF) + 0.7152 * ((pixel >> 8) & 0xFF) +
                 0.0722 * (pixel & 0xFF)) /
                255.0;
      } else if (format == CAIRO_FORMAT_A8) {
        value = data[y * stride + x] / 255.0;
      } else {
        throw core::InputError(path.string(), 0, "unsupported PNG pixel format");
      }
      raster.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(raster.width) +
                    static_cast<std::size_t>(x)] = static_cast<float>(value);
    }
  }
  return raster;
}

}  // namespace shapeproc::io
