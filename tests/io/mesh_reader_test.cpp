#include "libshapeproc/io/mesh_reader.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

using testing::TempDir;

// Two unit tetrahedra, 3 apart along x, in one OBJ group "pair", and a cube... kept small: the
// second group holds one more tetrahedron.
const char* kGroupedObj = R"(# test
o pair
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
v 3 0 0
v 4 0 0
v 3 1 0
v 3 0 1
f 1 3 2
f 1 2 4
f 1 4 3
f 2 3 4
f 5 7 6
f 5 6 8
f 5 8 7
f 6 7 8
g single
v 0 5 0
v 1 5 0
v 0 6 0
v 0 5 1
f 9 11 10
f 9 10 12
f 9 12 11
f 10 11 12
)";

TEST(MeshReader, ShippedPebblesByComponentsAndGroups) {
  const auto path = testing::data_path("mesh/pebbles.obj");
  const geometry::Scene components = read_mesh_scene(path, {});
  EXPECT_EQ(components.dimension, 3);
  ASSERT_EQ(components.elements.size(), 12u);
  ReaderOptions groups;
  groups.mesh_split = MeshSplit::groups;
  const geometry::Scene grouped = read_mesh_scene(path, groups);
  ASSERT_EQ(grouped.elements.size(), 12u);
  EXPECT_EQ(grouped.shapes[0].name, "sphere1");
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_LT((components.elements[i].position - grouped.elements[i].position).norm(), 1e-12);
    // The window is the scene's bounding box: every element lies inside it.
    const auto box = geometry::bounding_box(components.placed_shape(i));
    EXPECT_TRUE(components.window.contains(box));
  }
}

TEST(MeshReader, GroupsOrComponents) {
  const TempDir dir;
  const auto path = dir.write("pair.obj", kGroupedObj);
  EXPECT_EQ(read_mesh_scene(path, {}).elements.size(), 3u);
  ReaderOptions groups;
  groups.mesh_split = MeshSplit::groups;
  const geometry::Scene scene = read_mesh_scene(path, groups);
  ASSERT_EQ(scene.elements.size(), 2u);
  EXPECT_EQ(geometry::primitive_count(scene.shapes[0]), 8u);
  EXPECT_EQ(scene.shapes[1].name, "single");
  EXPECT_NEAR(scene.elements[0].position.x(), 2.0, 1e-6);
}

// OBJ text of axis-aligned boxes, each 8 vertices and 12 outward triangles.
std::string boxes_obj(const std::vector<std::array<double, 6>>& boxes) {
  std::string v, f;
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  int offset = 1;
  for (const auto& b : boxes) {
    for (double x : {b[0], b[1]})
      for (double y : {b[2], b[3]})
        for (double z : {b[4], b[5]})
          v += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    for (const auto& q : quads) {
      f += "f " + std::to_string(q[0] + offset) + " " + std::to_string(q[1] + offset) + " " +
           std::to_string(q[2] + offset) + "\n";
      f += "f " + std::to_string(q[0] + offset) + " " + std::to_string(q[2] + offset) + " " +
           std::to_string(q[3] + offset) + "\n";
    }
    offset += 8;
  }
  return v + f;
}

// A mesh tile on the box [0, 10]³: a box cut by the face x = 10 (its pieces [8, 10] and [0, 1]),
// one cut along the edge x = y = 10 (four pieces), and a whole box. Read with --tile, the pieces
// join across the faces into whole, unwrapped elements placed inside the window; without, every
// piece is an element.
TEST(MeshReader, ATilesPiecesJoinAcrossTheWindowsFaces) {
  const TempDir dir;
  const auto path = dir.write("tile.obj", boxes_obj({{8, 10, 1, 3, 1, 3},
                                                     {0, 1, 1, 3, 1, 3},
                                                     {9, 10, 9, 10, 5, 6},
                                                     {0, 1, 9, 10, 5, 6},
                                                     {9, 10, 0, 1, 5, 6},
                                                     {0, 1, 0, 1, 5, 6},
                                                     {4, 6, 4, 6, 4, 6}}));
  ReaderOptions options;
  options.window = WindowOption::parse("0,10,0,10,0,10");
  EXPECT_EQ(read_mesh_scene(path, options).elements.size(), 7u);
  options.tile = true;
  const geometry::Scene tile = read_mesh_scene(path, options);
  ASSERT_EQ(tile.elements.size(), 3u);
  std::vector<geometry::Vec3> sizes;
  for (const geometry::Shape& shape : tile.shapes) sizes.push_back(bounding_box(shape).sizes());
  EXPECT_TRUE(sizes[0].isApprox(geometry::Vec3(3, 2, 2), 1e-9)) << sizes[0].transpose();
  EXPECT_TRUE(sizes[1].isApprox(geometry::Vec3(2, 2, 1), 1e-9)) << sizes[1].transpose();
  EXPECT_TRUE(sizes[2].isApprox(geometry::Vec3(2, 2, 2), 1e-9)) << sizes[2].transpose();
  EXPECT_TRUE(tile.elements[0].position.isApprox(geometry::Vec3(9.5, 2, 2), 1e-9));
  // The corner box's centre (10, 10, 5.5) lies on the faces: its place is its image inside.
  EXPECT_TRUE(tile.elements[1].position.isApprox(geometry::Vec3(0, 0, 5.5), 1e-9))
      << tile.elements[1].position.transpose();
  ASSERT_FALSE(tile.notes.empty());
  EXPECT_NE(tile.notes[0].find("6 pieces"), std::string::npos) << tile.notes[0];
}

TEST(MeshReader, OffPolygonsStlAndWindowOption) {
  const TempDir dir;
  // A cube with quad faces: 6 quads become 12 triangles.
  const auto off =
      dir.write("cube.off",
                "OFF\n8 6 0\n\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  ReaderOptions options;
  options.window = WindowOption::parse("-1,2,-1,2,-1,2");
  const geometry::Scene cube = read_mesh_scene(off, options);
  ASSERT_EQ(cube.elements.size(), 1u);
  EXPECT_EQ(geometry::primitive_count(cube.shapes[0]), 12u);
  EXPECT_DOUBLE_EQ(cube.window_measure(), 27.0);
  EXPECT_EQ(cube.elements[0].position, geometry::Vec3(0.5, 0.5, 0.5));

  const auto stl = dir.write("tet.stl", R"(solid t
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0 1 0
vertex 1 0 0
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 0 0 1
endloop
endfacet
facet normal -1 0 0
outer loop
vertex 0 0 0
vertex 0 0 1
vertex 0 1 0
endloop
endfacet
facet normal 1 1 1
outer loop
vertex 1 0 0
vertex 0 1 0
vertex 0 0 1
endloop
endfacet
endsolid t
)");
  const geometry::Scene tet = read_mesh_scene(stl, {});
  ASSERT_EQ(tet.elements.size(), 1u);
  const auto& mesh = std::get<geometry::MeshShape>(tet.shapes[0].geometry).mesh;
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.vertices.size(), 4u);  // STL corners are merged into shared vertices
}

struct BadMesh {
  const char* name;
  const char* file;
  const char* text;
  const char* message;
};

class MeshBadInput : public ::testing::TestWithParam<BadMesh> {};

TEST_P(MeshBadInput, ThrowsInputErrorNamingTheFile) {
  const BadMesh& bad = GetParam();
  const TempDir dir;
  const auto path = dir.write(bad.file, bad.text);
  try {
    read_mesh_scene(path, {});
    FAIL() << bad.name;
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.file), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, MeshBadInput,
    ::testing::Values(
        BadMesh{"empty", "e.off", "", "empty"},
        BadMesh{"garbage", "g.off", "this is not a mesh\n", "not OFF"},
        BadMesh{"non_manifold", "nm.off",
                "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n",
                "non-manifold"},
        BadMesh{"repeated_vertex", "rv.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 2\n",
                "invalid mesh"},
        BadMesh{"zero_area", "za.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 1\n3 0 1 2\n3 0 3 1\n",
                "zero area"},
        BadMesh{"no_faces", "nf.obj", "v 0 0 0\nv 1 0 0\n", "no triangles"},
        BadMesh{"flat", "flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "zero size"}),
    [](const ::testing::TestParamInfo<BadMesh>& param_info) {
      return std::string(param_info.param.name);
    });

TEST(MeshReader, OptionMisuse) {
  const TempDir dir;
  const auto off = dir.write(
      "t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ReaderOptions groups;
  groups.mesh_split = MeshSplit::groups;
  EXPECT_THROW(read_mesh_scene(off, groups), core::UsageError);
  ReaderOptions flat_window;
  flat_window.window = WindowOption::parse("0,1,0,1");
  EXPECT_THROW(read_mesh_scene(off, flat_window), core::UsageError);
  EXPECT_EQ(read_mesh_scene(off, {}).elements.size(), 1u);
}

}  // namespace
}  // namespace shapeproc::io
