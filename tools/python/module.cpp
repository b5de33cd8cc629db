// The `shapeproc` Python module (docs/python.md): read an exemplar or make one from NumPy arrays,
// fit a shape process, sample outputs, measure and edit, write files. A thin layer: every function
// is one call of the library, with the GIL released while it computes.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/points_scene.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/model/model_edits.hpp"
#include "libshapeproc/pipeline/method_comparison.hpp"
#include "libshapeproc/pipeline/synthesis_run.hpp"
#include "tools/python/arrays.hpp"

namespace shapeproc::python {

namespace {

using Model = model::ShapeProcessModel;
using Scene = geometry::Scene;
using Release = py::call_guard<py::gil_scoped_release>;

Scene read_scene(const std::string& path, const std::string& category_by, bool tile,
                 const std::optional<py::array_t<double>>& window) {
  io::ReaderOptions options;
  options.category_by = io::CategoryRule::parse(category_by);
  options.tile = tile;
  if (window) {
    const int dimension = window->ndim() == 2 ? static_cast<int>(window->shape(1))
                                              : static_cast<int>(window->shape(0) / 2);
    options.window = io::WindowOption{dimension, window_from(*window, dimension)};
  }
  py::gil_scoped_release release;
  return io::read_scene(path, options);
}

Scene points(const py::array_t<double>& positions, std::optional<py::array_t<int>> categories,
             std::optional<py::array_t<double>> window, std::optional<py::array_t<double>> radii,
             std::vector<std::string> category_names) {
  io::PointsInput input;
  input.positions = positions_from(positions, input.dimension);
  if (categories) {
    const auto c = categories->unchecked<1>();
    for (py::ssize_t i = 0; i < c.shape(0); ++i) input.categories.push_back(c(i));
  }
  if (radii) {
    const auto r = radii->unchecked<1>();
    for (py::ssize_t i = 0; i < r.shape(0); ++i) input.radii.push_back(r(i));
  }
  if (window) {
    input.window = window_from(*window, input.dimension);
  } else {  // the positions' bounding box
    for (const geometry::Vec3& p : input.positions) input.window.extend(p);
  }
  input.category_names = std::move(category_names);
  return io::points_scene(input);
}

Model fit(const Scene& scene, const std::string& estimator, bool tile) {
  fit::ExemplarFitOptions options = fit::exemplar_fit_options(tile);
  if (estimator == "mpl") {
    options.likelihood.reset();
  } else if (estimator == "mle") {
    options.likelihood_elements = scene.elements.size();
  } else if (estimator != "auto") {
    throw std::invalid_argument("estimator: expected auto, mpl or mle, got '" + estimator + "'");
  }
  return fit::fit_exemplar(scene, options).result.model;
}

// An output of `model` on a torus of `size`, from empty, as `shapeproc sample` makes it.
Scene sample(const Model& model, const std::vector<double>& size, std::uint64_t seed) {
  const geometry::Domain domain = geometry::Domain::from_sizes(size, geometry::Boundary::torus);
  pipeline::SamplingRequest request;
  request.chains.seed = seed;
  request.chains.record.command = "python";
  Scene out = std::move(pipeline::sample_model(model, domain, request).results.front().scene);
  std::string sides;
  for (double side : size) sides += (sides.empty() ? "" : ",") + std::to_string(side);
  out.notes.push_back("sampled by shapeproc.sample: seed " + std::to_string(seed) + ", size " +
                      sides + ", torus, from empty");
  return out;
}

// A JSON string of `text`.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

// What a file written from Python records: the given provenance, else the scene's notes (an
// output's seed and size).
void write_scene(const Scene& scene, const std::string& path, const std::string& provenance) {
  std::string json = provenance;
  if (json.empty()) {
    json = "{\"software\": " + quoted(std::string("shapeproc ") + SHAPEPROC_VERSION) +
           ", \"interface\": \"python\", \"notes\": [";
    for (std::size_t i = 0; i < scene.notes.size(); ++i)
      json += (i ? ", " : "") + quoted(scene.notes[i]);
    json += "]}";
  }
  io::write_scene(scene, path, io::Provenance{json});
}

py::dict measure(const Scene& scene) {
  metrics::SceneStatistics s;
  {
    py::gil_scoped_release release;
    s = metrics::compute_statistics(scene, {}, core::Random(1));
  }
  py::dict out;
  out["categories"] = s.categories;
  out["counts"] = s.counts;
  out["intensity"] = vector_array(s.intensity);
  out["mean_spacing"] = s.mean_spacing;
  out["range"] = s.range;
  out["nearest"] = vector_array(s.all.nearest.values);
  out["nearest_weights"] = vector_array(s.all.nearest.weights);
  out["mean_nearest"] = s.mean_nearest();
  out["g_r"] = vector_array(s.correlation_r);
  out["g"] = vector_array(s.correlation);
  out["overlapping_pairs"] = s.collisions.pairs.size();
  return out;
}

// Every method of `methods` on the exemplar at `path`, with the page, as `shapeproc compare`.
py::list compare(const std::string& path, const std::string& size, const std::string& directory,
                 const std::optional<std::string>& methods, std::uint64_t seed,
                 const std::string& category_by, bool tile) {
  pipeline::MethodComparisonRequest request;
  request.exemplar = path;
  request.reader.category_by = io::CategoryRule::parse(category_by);
  request.reader.tile = tile;
  request.size = size;
  request.seed = seed;
  if (methods) request.methods = pipeline::parse_compared_methods(*methods);
  request.directory = directory;
  request.command = "shapeproc.compare(" + path + ")";
  pipeline::MethodComparison done;
  {
    py::gil_scoped_release release;
    done = pipeline::compare_methods(request);
  }
  py::list out;
  for (const pipeline::MethodRun& run : done.runs) {
    py::dict d;
    d["method"] = run.method;
    d["output"] = run.output;
    d["failure"] = run.failure;
    d["seconds"] = run.seconds;
    d["elements"] = run.elements;
    d["index"] = done.report.index;
    out.append(d);
  }
  return out;
}

std::vector<std::string> category_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const geometry::Category& c : scene.categories) names.push_back(c.name);
  return names;
}

void bind_scene(py::module_& m) {
  py::class_<Scene>(m, "Scene", "Elements in a window: an exemplar read or made, or an output")
      .def_property_readonly("dimension", [](const Scene& s) { return s.dimension; })
      .def_property_readonly("positions", &positions_array, "(n, dim) reference positions")
      .def_property_readonly("categories", &categories_array, "(n,) category indices")
      .def_property_readonly("category_names", &category_names)
      .def_property_readonly("window", &window_array, "(2, dim): lower and upper corners")
      .def_property_readonly("units", [](const Scene& s) { return s.units; })
      .def("__len__", [](const Scene& s) { return s.elements.size(); })
      .def("__repr__", [](const Scene& s) {
        return "<shapeproc.Scene " + std::to_string(s.dimension) + "D, " +
               std::to_string(s.elements.size()) + " elements, " +
               std::to_string(s.categories.size()) + " categories>";
      });
}

void bind_model(py::module_& m) {
  py::class_<Model>(m, "Model", "A fitted shape process")
      .def_property_readonly("categories",
                             [](const Model& model) {
                               std::vector<std::string> names;
                               for (const auto& c : model.categories) names.push_back(c.name);
                               return names;
                             })
      .def_property_readonly("beta",
                             [](const Model& model) {
                               std::vector<double> beta;
                               for (const auto& c : model.categories) beta.push_back(c.beta);
                               return vector_array(beta);
                             })
      .def_property_readonly("notes",
                             [](const Model& model) {
                               return model.fit ? model.fit->notes : std::vector<std::string>{};
                             })
      .def_property_readonly(
          "path",
          [](const Model& model) {
            return model::fit_path_name(model.fit ? model.fit->path
                                                  : model::FitPath::pseudo_likelihood);
          },
          "the path the fit took: its estimator and window")
      .def("to_json", &io::model_to_json)
      .def("save",
           [](const Model& model, const std::string& path) { io::write_model(model, path); })
      .def("scale_beta", &model::scale_intensities, py::arg("factor"),
           "multiply every category's intensity β by factor")
      .def("set_beta", &model::set_intensity, py::arg("category"), py::arg("beta"))
      .def("make_isotropic", &model::make_isotropic,
           "pool every pair's directions into one (an isotropic model)");
}

}  // namespace

}  // namespace shapeproc::python

PYBIND11_MODULE(shapeproc, m) {
  using namespace shapeproc::python;
  namespace io = shapeproc::io;
  m.doc() = "Statistical discrete-element texture synthesis: the shape process of libshapeproc";
  m.attr("__version__") = SHAPEPROC_VERSION;
  bind_scene(m);
  bind_model(m);
  m.def("read", &read_scene, py::arg("path"), py::arg("category_by") = "none",
        py::arg("tile") = false, py::arg("window") = py::none(),
        "Read an exemplar (SVG, CSV, OBJ, PLY, OFF, STL) as `shapeproc` reads it");
  m.def("points", &points, py::arg("positions"), py::arg("categories") = py::none(),
        py::arg("window") = py::none(), py::arg("radii") = py::none(),
        py::arg("category_names") = std::vector<std::string>{},
        "A scene of points (or discs of the given radii) from NumPy arrays");
  m.def("fit", &fit, py::arg("scene"), py::arg("estimator") = "auto", py::arg("tile") = false,
        Release(), "Fit a shape process to an exemplar, as `shapeproc fit` does");
  m.def(
      "load_model", [](const std::string& path) { return io::read_model(path); }, py::arg("path"),
      "Read a model file written by `shapeproc fit` or Model.save");
  m.def("sample", &sample, py::arg("model"), py::arg("size"), py::arg("seed") = 1, Release(),
        "An output of the model on a torus of the given size, from empty");
  m.def("compare", &compare, py::arg("path"), py::arg("size"), py::arg("directory"),
        py::arg("methods") = py::none(), py::arg("seed") = 1, py::arg("category_by") = "none",
        py::arg("tile") = false,
        "Every synthesis method on one exemplar, each output and a page comparing them written "
        "to the directory, as `shapeproc compare`; a dict per method (failure: why it failed, "
        "empty when it ran)");
  m.def("measure", &measure, py::arg("scene"),
        "Counts, intensities, nearest-neighbour distances and g(r), as `shapeproc stats`");
  m.def("write", &write_scene, py::arg("scene"), py::arg("path"), py::arg("provenance") = "",
        "Write a scene (.svg, .csv, .obj, .ply) with its provenance (a JSON text; by default the "
        "scene's notes, which hold an output's seed and size)");
}
