// Reading and writing scenes by file extension: the entry point the command line uses.
#pragma once

#include <filesystem>
#include <string>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/reader_options.hpp"
#include "libshapeproc/io/scene_writers.hpp"

namespace shapeproc::io {

// .svg (2D), .obj/.ply/.off/.stl (3D meshes), .csv (point patterns). Throws InputError.
geometry::Scene read_scene(const std::filesystem::path& file, const ReaderOptions& options);

// .svg, .obj, .ply or .csv after the extension of `file`, written atomically (temporary file
// renamed into place). A CSV gets its provenance in a sidecar `FILE.json`. Throws UsageError for
// an unknown extension or a format that cannot hold the scene's dimension.
void write_scene(const geometry::Scene& scene, const std::filesystem::path& file,
                 const Provenance& provenance);

// The provenance record a shapeproc output carries (SVG <metadata id="shapeproc">, the OBJ/PLY
// provenance comment, a CSV's JSON sidecar), or an empty string when the file has none.
std::string read_provenance(const std::filesystem::path& file);

}  // namespace shapeproc::io
