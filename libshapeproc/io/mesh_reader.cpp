#include "libshapeproc/io/mesh_reader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/detail/mesh_header_check.hpp"
#include "libshapeproc/io/detail/mesh_tile_seams.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

// Collects what OpenMesh reports while alive (it reports rejected faces on its error stream,
// which writes to std::cerr). std::cerr's buffer is swapped rather than OpenMesh's stream
// reconnected, because OpenMesh's disconnect leaks its target. Not for concurrent use.
class CaptureOpenMeshErrors {
 public:
  CaptureOpenMeshErrors() : previous_(std::cerr.rdbuf(buffer_.rdbuf())) {
    ::omlog().disable();
    ::omout().disable();
  }
  ~CaptureOpenMeshErrors() {
    ::omerr().flush();
    std::cerr.rdbuf(previous_);
  }
  CaptureOpenMeshErrors(const CaptureOpenMeshErrors&) = delete;
  CaptureOpenMeshErrors& operator=(const CaptureOpenMeshErrors&) = delete;

  std::string first_line() {
    ::omerr().flush();
    const std::string text = buffer_.str();
    return std::string(trim(text.substr(0, text.find('\n'))));
  }

 private:
  std::ostringstream buffer_;
  std::streambuf* previous_;
};

// The OBJ group (from `o`/`g` lines) of each triangle, in file order, polygons fanned.
struct ObjGroups {
  std::vector<std::string> names;
  std::vector<int> of_triangle;
};

ObjGroups scan_obj_groups(const std::filesystem::path& file) {
  std::ifstream in(file);
  ObjGroups groups;
  int current = -1;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "o" || keyword == "g") {
      std::string name, word;
      while (tokens >> word) name += (name.empty() ? "" : " ") + word;
      if (name.empty()) name = "unnamed";
      const auto found = std::find(groups.names.begin(), groups.names.end(), name);
      current = static_cast<int>(found - groups.names.begin());
      if (found == groups.names.end()) groups.names.push_back(name);
    } else if (keyword == "f") {
      int corners = 0;
      std::string word;
      while (tokens >> word) ++corners;
      if (current < 0) {
        groups.names.push_back("default");
        current = static_cast<int>(groups.names.size() - 1);
      }
      for (int i = 2; i < corners; ++i) groups.of_triangle.push_back(current);
    }
  }
  return groups;
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

namespace {

// The triangles as read: vertices, vertex triples and their bounding box.
struct MeshTriangles {
  std::vector<geometry::Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  geometry::Box3 box;
};

// Reads the file with OpenMesh, then checks what it read: finite vertices, no degenerate
// triangle. Any problem is an InputError naming the file.
MeshTriangles read_triangles(const std::string& name, const std::string& ext) {
  MeshTriangles out;
  OmMesh mesh;
  std::string complaint;
  bool read = false;
  {
    CaptureOpenMeshErrors capture;
    OpenMesh::IO::Options io_options;
    read = OpenMesh::IO::read_mesh(mesh, name, io_options);
    complaint = capture.first_line();
  }
  if (!read) {
    throw core::InputError(name, 0,
                           "cannot read as " + to_lower(ext) + " mesh" +
                               (complaint.empty() ? "" : " (" + complaint + ")"));
  }
  if (complaint.find("complex") != std::string::npos) {
    throw core::InputError(name, 0,
                           "non-manifold or inconsistently oriented faces (" + complaint + ")");
  }
  if (!complaint.empty()) throw core::InputError(name, 0, "invalid mesh (" + complaint + ")");
  if (mesh.n_faces() == 0) throw core::InputError(name, 0, "no triangles");

  // Geometry checks on the triangles as read.
  std::vector<geometry::Vec3>& points = out.points;
  points.resize(mesh.n_vertices());
  geometry::Box3& box = out.box;
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    points[vh.idx()] = geometry::Vec3(p[0], p[1], p[2]);
    if (!points[vh.idx()].allFinite()) {
      throw core::InputError(name, 0,
                             "vertex " + std::to_string(vh.idx()) + " has a non-finite coordinate");
    }
  }
  std::vector<std::array<int, 3>>& triangles = out.triangles;
  triangles.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) {
      t[k++] = vh.idx();
      box.extend(points[vh.idx()]);
    }
    triangles.push_back(t);
  }
  const double scale = box.diagonal().squaredNorm();
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    const double twice_area =
        (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
    if (!(twice_area > 1e-14 * scale)) {
      throw core::InputError(name, 0, "degenerate triangle (zero area): face " + std::to_string(f));
    }
  }

  return out;
}

// Each triangle's element (connected components, or OBJ groups) and the elements' names.
std::vector<int> elements_of_triangles(const std::filesystem::path& file, const std::string& name,
                                       const MeshTriangles& mesh, const ReaderOptions& options,
                                       std::vector<std::string>& element_names) {
  const std::vector<geometry::Vec3>& points = mesh.points;
  const std::vector<std::array<int, 3>>& triangles = mesh.triangles;
  std::vector<int> element_of_triangle(triangles.size());
  if (options.mesh_split == MeshSplit::groups) {
    const ObjGroups groups = scan_obj_groups(file);
    if (groups.of_triangle.size() != triangles.size()) {
      throw core::InputError(name, 0,
                             "the faces read do not match the `f` lines (" +
                                 std::to_string(triangles.size()) + " vs " +
                                 std::to_string(groups.of_triangle.size()) + ")");
    }
    element_of_triangle = groups.of_triangle;
    element_names = groups.names;
  } else {
    std::vector<std::size_t> parent(points.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& t : triangles) {
      for (int k = 1; k < 3; ++k) {
        const std::size_t a = find_root(parent, t[0]), b = find_root(parent, t[k]);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
    std::map<std::size_t, int> component;
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      const std::size_t root = find_root(parent, triangles[f][0]);
      const auto inserted = component.emplace(root, static_cast<int>(component.size()));
      if (inserted.second)
        element_names.push_back("component " + std::to_string(inserted.first->second));
      element_of_triangle[f] = inserted.first->second;
    }
  }

  return element_of_triangle;
}

// The scene's elements: each element's triangles with its own vertices, moved by whole periods
// where a tile's seams joined them, placed inside the window.
void add_elements(const MeshTriangles& mesh, const std::vector<int>& element_of_triangle,
                  const std::vector<std::string>& element_names,
                  const std::vector<Eigen::Vector3i>& periods_of_triangle,
                  const geometry::Box3& window, geometry::Scene& scene) {
  const std::vector<geometry::Vec3>& points = mesh.points;
  const std::vector<std::array<int, 3>>& triangles = mesh.triangles;
  const int category = scene.category_index("default");
  std::vector<geometry::TriangleMesh> pieces(element_names.size());
  // Each element's own index of a mesh vertex, by (element, vertex): a table per element the
  // size of the whole mesh took 4.6 GB for 20,000 separate triangles.
  std::unordered_map<std::uint64_t, int> local;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const int e = element_of_triangle[f];
    geometry::TriangleMesh& piece = pieces[e];
    std::array<int, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const int v = triangles[f][k];
      const std::uint64_t key = static_cast<std::uint64_t>(e) * points.size() + v;
      const auto [at, added] = local.try_emplace(key, static_cast<int>(piece.vertices.size()));
      if (added) {
        geometry::Vec3 point = points[v];
        if (!periods_of_triangle.empty())
          point += periods_of_triangle[f].cast<double>().cwiseProduct(window.sizes());
        piece.vertices.push_back(point);
      }
      t[k] = at->second;
    }
    piece.triangles.push_back(t);
  }
  for (std::size_t e = 0; e < pieces.size(); ++e) {
    if (pieces[e].triangles.empty()) continue;
    const std::size_t added = geometry::add_element(
        scene, geometry::Shape{geometry::MeshShape{std::move(pieces[e])}, element_names[e]},
        category);
    // A whole element of a tile may reach past the window: its place is its image inside.
    if (!periods_of_triangle.empty())
      scene.elements[added].position = wrap_into(scene.elements[added].position, window);
  }
}

}  // namespace

geometry::Scene read_mesh_scene(const std::filesystem::path& file, const ReaderOptions& options) {
  const std::string name = file.string();
  const std::string ext = extension_of(file);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw core::InputError(name, 0, "no such file");
  if (std::filesystem::file_size(file, ec) == 0)
    throw core::InputError(name, 0, "the file is empty");
  if (!std::ifstream(file)) throw core::InputError(name, 0, "cannot open the file for reading");
  if (options.mesh_split == MeshSplit::groups && ext != "obj") {
    throw core::UsageError("{mesh_split}=groups needs an OBJ file, got " + name);
  }
  check_mesh_header(file);
  const MeshTriangles mesh = read_triangles(name, ext);
  const std::vector<geometry::Vec3>& points = mesh.points;
  const std::vector<std::array<int, 3>>& triangles = mesh.triangles;
  const geometry::Box3& box = mesh.box;
  std::vector<std::string> element_names;
  std::vector<int> element_of_triangle =
      elements_of_triangles(file, name, mesh, options, element_names);

  if (options.window && options.window->dimension != 3)
    throw core::UsageError("{window} for a mesh needs six numbers (x, y and z ranges)");
  const geometry::Box3 window = options.window ? options.window->box : box;
  // A tile: pieces cut by the window's faces join their counterparts across the opposite faces,
  // each moved by whole periods to make its element whole (mesh_tile_seams.hpp).
  std::vector<Eigen::Vector3i> periods_of_triangle;
  SeamJoin seams;
  if (options.tile && options.mesh_split == MeshSplit::components &&
      window.sizes().minCoeff() > 0.0) {
    seams = join_across_faces(points, triangles, element_of_triangle,
                              static_cast<int>(element_names.size()), window);
    periods_of_triangle.resize(triangles.size());
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      const auto piece = static_cast<std::size_t>(element_of_triangle[f]);
      periods_of_triangle[f] = seams.periods_of_piece[piece];
      element_of_triangle[f] = seams.element_of_piece[piece];
    }
    element_names.resize(static_cast<std::size_t>(seams.elements));
    for (int e = 0; e < seams.elements; ++e)
      element_names[static_cast<std::size_t>(e)] = "component " + std::to_string(e);
  }

  geometry::Scene scene;
  scene.dimension = 3;
  scene.units = "1";
  add_elements(mesh, element_of_triangle, element_names, periods_of_triangle, window, scene);
  if (seams.joined_pieces > 0)
    scene.notes.push_back("tile: " + std::to_string(seams.joined_pieces) +
                          " pieces cut by the window's faces joined their counterparts across "
                          "them into whole elements");
  if (seams.wraps)
    scene.notes.push_back(
        "tile: a motif meets itself around the repeat; it is kept as one "
        "element, unwrapped as far as it first joined");
  scene.window = window;
  const geometry::Vec3 sizes = scene.window.sizes();
  if (!(sizes.minCoeff() > 0.0)) {
    throw core::InputError(name, 0, "the window has zero size (a flat scene): give {window}");
  }
  return scene;
}

}  // namespace shapeproc::io
