// Reading 3D exemplars from mesh files (OBJ, PLY, OFF, STL) through OpenMesh.
#pragma once

#include <filesystem>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/reader_options.hpp"

namespace shapeproc::io {

// Reads a triangle-mesh scene. Elements are the connected components of the mesh
// (options.mesh_split == components) or the OBJ `o`/`g` groups (groups; OBJ only). Polygons are
// split into triangle fans. The window is options.window (3D) or the bounding box of the scene.
// With options.tile (components only), pieces cut by the window's faces join their counterparts
// across the opposite faces into whole elements (mesh_tile_seams.hpp), placed inside the window.
// Coordinates are read in single precision by OpenMesh's readers.
//
// Throws InputError naming the file for: unreadable or empty files, files OpenMesh cannot parse,
// non-manifold or inconsistently oriented faces, faces that repeat a vertex, zero-area triangles,
// non-finite coordinates, no triangles, and a window of zero size.
geometry::Scene read_mesh_scene(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace shapeproc::io
