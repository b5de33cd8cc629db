// Checks a mesh file (OBJ, OFF, PLY, STL) before OpenMesh reads it. OpenMesh's readers trust what
// a header declares: a PLY or OFF header claiming 10^9 vertices made them allocate 64 GB, and some
// malformed headers crashed them. Here the counts a header declares must be non-negative and fit
// in the file's size, the header must be one of the forms OpenMesh reads safely, and OBJ faces
// must name vertices that exist. Everything else (the numbers themselves, manifoldness) is left
// to the reader.
#pragma once

#include <filesystem>

namespace shapeproc::io {

// Throws core::InputError naming the file and what is wrong.
void check_mesh_header(const std::filesystem::path& file);

}  // namespace shapeproc::io
