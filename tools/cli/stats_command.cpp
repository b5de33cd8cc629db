// shapeproc stats SCENE [--against EXEMPLAR] [--json]: the metrics of docs/metrics.md.
#include "tools/cli/stats_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <memory>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/directions.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/commands.hpp"

namespace shapeproc::cli {

namespace {

// printf-style formatting of one number, for tables.
using core::format_fixed;
using core::format_general;

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json cdf_json(const metrics::Distribution& d, double range, int points = 33) {
  nlohmann::json r = nlohmann::json::array(), f = nlohmann::json::array();
  for (int k = 0; k < points; ++k) {
    const double x = range * k / (points - 1);
    r.push_back(x);
    f.push_back(d.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.cdf(x)));
  }
  return {{"r", r}, {"F", f}, {"samples", d.samples}, {"mean", number(d.mean())}};
}

// An axis as `stats` tables it: its components to two decimals.
std::string direction_components(const geometry::Vec3& v, int dimension) {
  std::ostringstream s;
  s << '(' << format_fixed(v.x(), 2) << ", " << format_fixed(v.y(), 2);
  if (dimension == 3) s << ", " << format_fixed(v.z(), 2);
  s << ')';
  return s.str();
}

std::string boundary_text(const metrics::SceneStatistics& s) {
  if (s.periodic()) return "torus";
  return s.edge == metrics::EdgeTreatment::border ? "open (border-corrected)"
                                                  : "open (no edge correction)";
}

void print_novelty(const metrics::Novelty& n, const std::string& unit, std::ostream& out) {
  const metrics::CopyMeasures &o = n.output, &c = n.chance;
  out << "novelty     against the exemplar tiled (tolerance " << format_general(n.tolerance, 3)
      << ' ' << unit << "; chance: the same elements placed at random)\n";
  out << "            copy share " << format_fixed(o.copy, 2) << " (chance "
      << format_fixed(c.copy, 2) << "), patch copy share " << format_fixed(o.patch, 2)
      << " (chance " << format_fixed(c.patch, 2) << "), largest copied patch "
      << format_fixed(o.largest_patch, 2) << " (chance " << format_fixed(c.largest_patch, 2)
      << "), repetition at the period " << format_fixed(o.repetition, 2) << " (chance "
      << format_fixed(c.repetition, 2) << ")\n";
  out << "            "
      << (n.lattice_exemplar ? "a lattice exemplar: its own repeat is its only faithful arrangement"
          : n.repeats_exemplar ? "repeats the exemplar"
                               : "a new arrangement")
      << '\n';
}

nlohmann::json novelty_json(const metrics::Novelty& n) {
  auto measures = [](const metrics::CopyMeasures& m) {
    return nlohmann::json{{"copy", m.copy},
                          {"patch", m.patch},
                          {"largest_patch", m.largest_patch},
                          {"repetition", m.repetition}};
  };
  return {{"tolerance", n.tolerance},
          {"output", measures(n.output)},
          {"chance", measures(n.chance)},
          {"lattice_exemplar", n.lattice_exemplar},
          {"repeats_exemplar", n.repeats_exemplar}};
}

void print_evaluation(const EvaluatedScene& scene, const Evaluation& e,
                      const std::string& reference, std::ostream& out) {
  const metrics::SceneStatistics& s = e.statistics;
  const char* area = s.dimension == 2 ? "²" : "³";
  const std::string unit = scene.scene.units;
  const geometry::Vec3 size = scene.scene.window.sizes();
  out << "scene       " << scene.file << ": " << s.dimension << "D, " << s.elements()
      << " elements, window " << format_general(size.x()) << " x " << format_general(size.y());
  if (s.dimension == 3) out << " x " << format_general(size.z());
  out << ' ' << unit << ", " << boundary_text(s) << '\n';
  for (std::size_t c = 0; c < s.categories.size(); ++c) {
    out << (c == 0 ? "intensity   " : "            ") << s.categories[c] << ": " << s.counts[c]
        << " elements, " << format_general(s.intensity[c]) << " per " << unit << area;
    if (e.comparison)
      out << "  (x" << format_fixed(e.comparison->intensity_ratio[c], 2) << " the exemplar's)";
    out << '\n';
  }
  const double fraction = s.elements() > 0 ? 100.0 * s.collisions.elements / s.elements() : 0.0;
  out << "collisions  " << s.collisions.pairs.size() << " overlapping pairs, "
      << s.collisions.elements << " elements (" << format_fixed(fraction, 1) << "%); "
      << s.collisions.touching.size() << " touching pairs\n";
  out << "distances   shape distance up to R = " << format_general(s.range) << ' ' << unit
      << (reference.empty() ? " (mean spacing)" : " (the exemplar's mean spacing)")
      << "; nearest: mean over elements of "
      << "the distance to the nearest neighbour (R if none); neighbours: mean count within R\n";
  out << "            axis  direction           nearest  neighbours";
  if (e.comparison) out << "  W1 nearest  W1 pairs";
  out << '\n';
  auto row = [&](const std::string& name, const std::string& direction,
                 const metrics::DirectionalStatistics& d, const metrics::DistributionDistances* w) {
    out << "            " << std::left << std::setw(6) << name << std::setw(20) << direction
        << std::right << std::setw(7) << format_general(d.nearest.mean(), 4) << std::setw(12)
        << format_fixed(d.neighbours, 2);
    if (w)
      out << std::setw(12) << format_fixed(w->nearest, 3) << std::setw(10)
          << format_fixed(w->pairs, 3);
    out << '\n';
  };
  row("all", "", s.all, e.comparison ? &e.comparison->all : nullptr);
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    row(std::to_string(k), direction_components(s.axes[k].direction, s.dimension), s.axes[k],
        e.comparison ? &e.comparison->axes[k] : nullptr);
  }
  if (e.comparison) {
    out << "            (W1 divided by the exemplar's mean nearest distance, "
        << format_general(e.comparison->scale) << ' ' << unit << ")\n";
  }
  out << "G(r), g(r)  ";
  const int columns = 6;
  for (int k = 1; k <= columns; ++k)
    out << std::setw(8) << format_general(s.range * k / columns, 3);
  out << "  r\n            ";
  for (int k = 1; k <= columns; ++k)
    out << std::setw(8) << format_fixed(s.all.nearest.cdf(s.range * k / columns), 3);
  out << "  G\n            ";
  const std::size_t bins = s.correlation.size();
  for (int k = 1; k <= columns; ++k) {
    // g averaged over the histogram bins of the k-th sixth of the range.
    double sum = 0.0;
    int count = 0;
    for (std::size_t b = 0; b < bins; ++b) {
      const double r = s.correlation_r[b];
      if (r >= s.range * (k - 1) / columns && r < s.range * k / columns &&
          std::isfinite(s.correlation[b])) {
        sum += s.correlation[b];
        ++count;
      }
    }
    out << std::setw(8) << (count > 0 ? format_fixed(sum / count, 3) : "-");
  }
  out << "  g\n";
  if (e.neighbourhood) {
    const metrics::NeighbourhoodDistance& n = *e.neighbourhood;
    out << "neighbourhood distance (Davison eq. 5, Ma eq. 1): " << format_general(n.mean) << ' '
        << unit << "² = " << format_fixed(n.normalised, 3) << " a² (radius "
        << format_general(n.radius) << ' ' << unit << ", " << format_fixed(n.mean_neighbours, 1)
        << " neighbours, " << n.output_centres << " centres)\n";
  }
  if (e.novelty) print_novelty(*e.novelty, unit, out);
  out << "time        " << format_fixed(s.seconds + 0.0, 3) << " s\n";
}

}  // namespace

EvaluatedScene read_evaluated_scene(const std::string& file, const ReaderFlags& reader,
                                    const std::string& boundary) {
  EvaluatedScene e;
  e.file = file;
  e.record = io::read_synthesis_record(file);
  // A shapeproc output is read as written (its elements are its groups): --tile is for exemplars.
  io::ReaderOptions options = reader.options();
  if (e.record) options.tile = false;
  e.scene = io::read_scene(file, options);
  // A synthesised output's window is its domain box, which its record holds: mesh files have no
  // window, and their elements' bounds (wrapped across a torus) are not it.
  if (e.record && static_cast<int>(e.record->size.size()) == e.scene.dimension) {
    geometry::Vec3 size = geometry::Vec3::Zero();
    for (int axis = 0; axis < e.scene.dimension; ++axis)
      size[axis] = e.record->size[static_cast<std::size_t>(axis)];
    e.scene.window = geometry::Box3(geometry::Vec3::Zero(), size);
  }
  if (boundary == "torus") {
    e.boundary = geometry::Boundary::torus;
  } else if (boundary == "auto" && e.record) {
    e.boundary = e.record->boundary;
  } else if (boundary == "auto" && options.tile) {
    e.boundary = geometry::Boundary::torus;  // a seamless tile is one period of a torus
  }
  if (e.scene.elements.empty())
    throw core::InputError(file, 0, "the scene has no elements to measure");
  return e;
}

EvaluatedScene read_exemplar(const std::string& file, const ReaderFlags& reader,
                             const MetricFlags& flags) {
  return read_evaluated_scene(file, reader, flags.boundary == "torus" ? "auto" : flags.boundary);
}

void MetricFlags::add_to(CLI::App& command) {
  command
      .add_option(
          "--boundary", boundary,
          "auto (a shapeproc output's own boundary, a --tile torus, else open), torus or open")
      ->check(CLI::IsMember({"auto", "torus", "open"}))
      ->capture_default_str();
  command.add_option("--edge", edge, "edge treatment of open windows: auto, border or none")
      ->check(CLI::IsMember({"auto", "border", "none"}))
      ->capture_default_str();
  command.add_option("--range", range,
                     "distances up to R (default: the exemplar's mean spacing (|W|/n)^(1/dim))");
  command.add_option("--neighbourhood", neighbourhood,
                     "neighbourhood radius (default: twice the exemplar's mean spacing)");
  command.add_option("--directions", directions,
                     "canonical directions: 2D an even number or 1 (default 8); 3D 12 or 1");
  command.add_option("--direction", direction, "relative orientation: gravitation or centroid")
      ->check(CLI::IsMember({"gravitation", "centroid"}))
      ->capture_default_str();
  command
      .add_option("--proxy-tolerance", proxy_tolerance,
                  "proxy error bound, fraction of each element's diagonal")
      ->capture_default_str();
}

metrics::StatisticsOptions MetricFlags::options(const EvaluatedScene& scene,
                                                double at_range) const {
  if (!(range >= 0)) throw core::UsageError("--range must be positive");
  if (!(neighbourhood >= 0)) throw core::UsageError("--neighbourhood must be positive");
  if (!(proxy_tolerance > 0 && proxy_tolerance < 1))
    throw core::UsageError("--proxy-tolerance must be in (0, 1)");
  metrics::StatisticsOptions o;
  o.measurement.direction = direction_kind(direction);
  o.measurement.directions = geometry::directions_or_default(directions, scene.scene.dimension);
  o.measurement.periodic = scene.boundary == geometry::Boundary::torus;
  o.measurement.proxy.tolerance = proxy_tolerance;
  try {
    geometry::DirectionBins bins(scene.scene.dimension, o.measurement.directions);
  } catch (const std::invalid_argument& e) {
    throw core::UsageError(std::string("--directions: ") + e.what());
  }
  o.edge = edge == "border" ? metrics::EdgeTreatment::border
           : edge == "none" ? metrics::EdgeTreatment::none
                            : metrics::EdgeTreatment::automatic;
  o.range = at_range > 0 ? at_range : range;
  return o;
}

nlohmann::json MetricFlags::to_json() const {
  return {{"boundary", boundary},
          {"edge", edge},
          {"range", range},
          {"neighbourhood", neighbourhood},
          {"directions", directions},
          {"direction", direction},
          {"proxy_tolerance", proxy_tolerance}};
}

Evaluation evaluate(const EvaluatedScene& scene, const MetricFlags& flags,
                    const EvaluatedScene* reference,
                    const metrics::SceneStatistics* reference_statistics,
                    const geometry::Scene* drawing) {
  Evaluation e;
  if (reference && reference->scene.dimension != scene.scene.dimension) {
    throw core::UsageError(scene.file + " is " + std::to_string(scene.scene.dimension) + "D but " +
                           reference->file + " is " + std::to_string(reference->scene.dimension) +
                           "D");
  }
  const double range = reference_statistics ? reference_statistics->range : 0.0;
  e.statistics =
      metrics::compute_statistics(scene.scene, flags.options(scene, range), core::Random(1));
  if (reference && reference_statistics) {
    e.comparison = metrics::compare(e.statistics, *reference_statistics);
    e.neighbourhood = metrics::average_neighbourhood_distance(
        scene.scene, scene.boundary, reference->scene, reference->boundary, flags.neighbourhood);
    e.novelty = metrics::measure_novelty(drawing ? *drawing : reference->scene, scene.scene,
                                         scene.boundary);
  }
  return e;
}

nlohmann::json evaluation_json(const EvaluatedScene& scene, const Evaluation& e) {
  const metrics::SceneStatistics& s = e.statistics;
  nlohmann::json categories = nlohmann::json::array();
  for (std::size_t c = 0; c < s.categories.size(); ++c) {
    nlohmann::json entry = {
        {"name", s.categories[c]}, {"count", s.counts[c]}, {"intensity", s.intensity[c]}};
    if (e.comparison) entry["intensity_ratio"] = number(e.comparison->intensity_ratio[c]);
    categories.push_back(entry);
  }
  auto directional = [&](const metrics::DirectionalStatistics& d,
                         const metrics::DistributionDistances* w) {
    nlohmann::json j = {{"neighbours", d.neighbours},
                        {"nearest", cdf_json(d.nearest, s.range)},
                        {"pairs", cdf_json(d.pairs, s.range)}};
    if (w) j["w1"] = {{"nearest", number(w->nearest)}, {"pairs", number(w->pairs)}};
    return j;
  };
  nlohmann::json axes = nlohmann::json::array();
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    nlohmann::json a = directional(s.axes[k], e.comparison ? &e.comparison->axes[k] : nullptr);
    const geometry::Vec3& v = s.axes[k].direction;
    a["direction"] =
        s.dimension == 2 ? nlohmann::json{v.x(), v.y()} : nlohmann::json{v.x(), v.y(), v.z()};
    axes.push_back(a);
  }
  nlohmann::json correlation = {{"r", s.correlation_r}, {"g", nlohmann::json::array()}};
  for (double g : s.correlation) correlation["g"].push_back(number(g));
  nlohmann::json collisions = {
      {"pairs", s.collisions.pairs.size()},
      {"elements", s.collisions.elements},
      {"fraction",
       s.elements() > 0 ? static_cast<double>(s.collisions.elements) / s.elements() : 0.0},
      {"list", s.collisions.pairs},
      {"touching", s.collisions.touching.size()},
      {"touching_list", s.collisions.touching}};
  nlohmann::json j = {{"scene", scene.file},
                      {"dimension", s.dimension},
                      {"boundary", geometry::to_string(s.boundary)},
                      {"edge", s.periodic()                               ? "none"
                               : s.edge == metrics::EdgeTreatment::border ? "border"
                                                                          : "none"},
                      {"elements", s.elements()},
                      {"window_measure", s.window_measure},
                      {"units", scene.scene.units},
                      {"range", s.range},
                      {"mean_spacing", s.mean_spacing},
                      {"categories", categories},
                      {"collisions", collisions},
                      {"all", directional(s.all, e.comparison ? &e.comparison->all : nullptr)},
                      {"axes", axes},
                      {"pair_correlation", correlation},
                      {"seconds", s.seconds}};
  if (e.comparison) j["w1_scale"] = e.comparison->scale;
  if (e.novelty) j["novelty"] = novelty_json(*e.novelty);
  if (e.neighbourhood) {
    const metrics::NeighbourhoodDistance& n = *e.neighbourhood;
    j["neighbourhood_distance"] = {{"mean", n.mean},
                                   {"normalised", n.normalised},
                                   {"radius", n.radius},
                                   {"mean_neighbours", n.mean_neighbours},
                                   {"output_centres", n.output_centres},
                                   {"exemplar_centres", n.exemplar_centres}};
  }
  return j;
}

void add_stats_command(CLI::App& app, Action& action) {
  struct StatsArguments {
    std::string scene, against;
    bool json = false;
    MetricFlags metrics;
    ReaderFlags reader;
  };
  auto args = std::make_shared<StatsArguments>();
  CLI::App* command =
      app.add_subcommand("stats",
                         "Metrics of an arrangement: collisions, intensity, directional distance "
                         "distributions, G(r), g(r); "
                         "with --against, distances to an exemplar's (W1, neighbourhood distance)");
  command
      ->add_option("SCENE", args->scene, "exemplar or output (.svg, .obj, .ply, .off, .stl, .csv)")
      ->required();
  command->add_option("--against", args->against, "the exemplar to compare with");
  command->add_flag("--json", args->json, "print JSON instead of text");
  args->metrics.add_to(*command);
  args->reader.add_to(*command);
  command->callback([&action, args] {
    action = [args](std::ostream& out) {
      std::optional<EvaluatedScene> reference;
      std::optional<metrics::SceneStatistics> reference_statistics;
      if (!args->against.empty()) {
        reference = read_exemplar(args->against, args->reader, args->metrics);
        reference_statistics = metrics::compute_statistics(
            reference->scene, args->metrics.options(*reference, 0.0), core::Random(1));
      }
      const EvaluatedScene scene =
          read_evaluated_scene(args->scene, args->reader, args->metrics.boundary);
      const Evaluation e = evaluate(scene, args->metrics, reference ? &*reference : nullptr,
                                    reference_statistics ? &*reference_statistics : nullptr);
      if (args->json) {
        nlohmann::json j = evaluation_json(scene, e);
        if (reference) j["against"] = args->against;
        j["options"] = args->metrics.to_json();
        out << j.dump(2) << '\n';
      } else {
        if (reference) out << "against     " << args->against << '\n';
        print_evaluation(scene, e, args->against, out);
      }
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
