// shapeproc measure EXEMPLAR: proxies, then d and o for every pair of elements within range.
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/geometry/directions.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/io/pair_csv.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

namespace {

struct MeasureArguments {
  std::string input;
  std::string output;
  double range = std::numeric_limits<double>::infinity();
  std::string distance = "shape";
  std::string direction = "gravitation";
  int directions = 0;  // 0: 8 in 2D, 12 in 3D
  bool periodic = false;
  double proxy_tolerance = geometry::ProxyOptions{}.tolerance;
  std::string proxy_out;
  ReaderFlags reader;
};

int run_measure(const MeasureArguments& args, const std::vector<std::string>& arguments,
                std::ostream& out) {
  const io::ReaderOptions reader = args.reader.options();
  if (!(args.range > 0)) throw core::UsageError("--range must be positive");
  if (!(args.proxy_tolerance >= 0 && args.proxy_tolerance < 1)) {
    throw core::UsageError(
        "--proxy-tolerance must be in [0, 1) (a fraction of the element's size)");
  }
  const geometry::Scene scene = io::read_scene(args.input, reader);

  geometry::MeasurementOptions options;
  options.distance = distance_kind(args.distance);
  options.direction = direction_kind(args.direction);
  options.directions = geometry::directions_or_default(args.directions, scene.dimension);
  options.periodic = args.periodic;
  options.proxy.tolerance = args.proxy_tolerance;

  core::Stopwatch watch;
  std::unique_ptr<geometry::PairMeasurer> measurer;
  try {
    measurer = std::make_unique<geometry::PairMeasurer>(scene, options);
  } catch (const std::invalid_argument& e) {
    throw core::UsageError(std::string("--directions: ") + e.what());
  }
  const double proxy_seconds = watch.seconds();
  watch.restart();
  const std::vector<geometry::PairRecord> pairs = measurer->all_pairs(scene.elements, args.range);
  const double measure_seconds = watch.seconds();

  const nlohmann::json parameters = {
      {"input", args.input},
      {"range", std::isfinite(args.range) ? nlohmann::json(args.range) : nlohmann::json("all")},
      {"distance", args.distance},
      {"direction", args.direction},
      {"directions", options.directions},
      {"periodic", args.periodic},
      {"proxy_tolerance", args.proxy_tolerance},
      {"reader", args.reader.to_json()}};
  const io::Provenance provenance = make_provenance("measure", arguments, parameters);
  if (!args.proxy_out.empty()) {
    geometry::Scene proxies = scene;
    for (std::size_t s = 0; s < proxies.shapes.size(); ++s) {
      proxies.shapes[s] = scene.dimension == 2 ? geometry::proxy_as_shape(measurer->proxies2()[s])
                                               : geometry::proxy_as_shape(measurer->proxies3()[s]);
    }
    io::write_scene(proxies, args.proxy_out, provenance);
  }

  std::ostream& report = args.output.empty() ? std::cerr : out;
  if (args.output.empty()) {
    io::write_pairs_csv(out, scene.dimension, pairs);
  } else {
    if (io::extension_of(args.output) != "csv")
      throw core::UsageError(args.output + ": pairs are written as .csv");
    io::write_pairs_csv(args.output, scene.dimension, pairs, provenance);
  }
  const geometry::ProxyStatistics& stats = measurer->statistics();
  const char* unit = scene.dimension == 2 ? "segments" : "triangles";
  report << std::fixed << std::setprecision(1) << "elements: " << scene.elements.size()
         << ", shapes: " << scene.shapes.size() << '\n'
         << "proxies:  " << stats.source_per_element << " -> " << stats.proxy_per_element << ' '
         << unit << " per element (tolerance " << std::setprecision(4) << args.proxy_tolerance
         << " of the diagonal), " << std::setprecision(0) << stats.mass_per_element
         << (scene.dimension == 2 ? " mass boundary edges" : " mass points") << " per element\n"
         << "pairs:    " << pairs.size() << (std::isfinite(args.range) ? " within range" : " (all)")
         << ", " << measurer->bins().axis_count() << " axis bins\n"
         << std::setprecision(3) << "time:     proxies " << proxy_seconds * 1e3
         << " ms, measurements " << measure_seconds * 1e3 << " ms\n";
  report.unsetf(std::ios::fixed);
  if (!args.output.empty()) report << "wrote " << args.output << '\n';
  return 0;
}

}  // namespace

void add_measure_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  auto args = std::make_shared<MeasureArguments>();
  CLI::App* command = app.add_subcommand(
      "measure",
      "Shortest distance and relative orientation of every pair of elements within range, "
      "on proxy geometry (one CSV row per pair: i,j,distance,ox,oy[,oz],axis)");
  command->add_option("EXEMPLAR", args->input, "input file")->required();
  command->add_option("-o,--output", args->output, "pairs CSV (standard output when absent)");
  command->add_option("--range", args->range,
                      "only pairs with distance below R (default: all pairs)");
  add_measurement_kind_options(*command, args->distance, args->direction);
  command->add_option(
      "--directions", args->directions,
      "canonical directions: 2D an even number or 1 (default 8); 3D 12 or 1 (default 12)");
  command->add_flag("--periodic", args->periodic, "the window is a torus (minimum-image offsets)");
  command
      ->add_option("--proxy-tolerance", args->proxy_tolerance,
                   "simplification error bound, fraction of each element's bounding-box diagonal")
      ->capture_default_str();
  command->add_option("--proxy-out", args->proxy_out,
                      "write the proxies (.svg for 2D, .obj or .ply for 3D)");
  args->reader.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) { return run_measure(*args, arguments, out); };
  });
}

}  // namespace shapeproc::cli
