// shapeproc stats SCENE [--against EXEMPLAR] [--json]: the metrics of docs/metrics.md.
#include "tools/cli/stats_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/directions.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/report/metrics_json.hpp"
#include "tools/cli/commands.hpp"

namespace shapeproc::cli {

namespace {

// printf-style formatting of one number, for tables.
using core::format_fixed;
using core::format_general;

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

void print_evaluation(const evaluation::EvaluatedScene& scene, const evaluation::Evaluation& e,
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
    if (!s.relations.empty())
      out << "; nested in another category " << format_fixed(s.relations.nested[c], 2)
          << ", overlapping one " << format_fixed(s.relations.overlapping[c], 2);
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

evaluation::MetricOptions MetricFlags::options() const {
  if (!(range >= 0)) throw core::UsageError("--range must be positive");
  if (!(neighbourhood >= 0)) throw core::UsageError("--neighbourhood must be positive");
  if (!(proxy_tolerance > 0 && proxy_tolerance < 1))
    throw core::UsageError("--proxy-tolerance must be in (0, 1)");
  evaluation::MetricOptions o;
  o.boundary = boundary == "torus"  ? evaluation::BoundaryChoice::torus
               : boundary == "open" ? evaluation::BoundaryChoice::open
                                    : evaluation::BoundaryChoice::automatic;
  o.edge = edge == "border" ? metrics::EdgeTreatment::border
           : edge == "none" ? metrics::EdgeTreatment::none
                            : metrics::EdgeTreatment::automatic;
  o.range = range;
  o.neighbourhood = neighbourhood;
  o.directions = directions;
  o.direction = direction_kind(direction);
  o.proxy_tolerance = proxy_tolerance;
  return o;
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
      const evaluation::MetricOptions options = args->metrics.options();
      const io::ReaderOptions reader = args->reader.options();
      std::optional<evaluation::EvaluatedScene> reference;
      std::optional<metrics::SceneStatistics> reference_statistics;
      if (!args->against.empty()) {
        reference = evaluation::read_exemplar(args->against, reader, options);
        reference_statistics = metrics::compute_statistics(
            reference->scene, evaluation::statistics_options(*reference, options, 0.0),
            core::Random(1));
      }
      const evaluation::EvaluatedScene scene =
          evaluation::read_evaluated_scene(args->scene, reader, options.boundary);
      const evaluation::Evaluation e =
          evaluation::evaluate(scene, options, reference ? &*reference : nullptr,
                               reference_statistics ? &*reference_statistics : nullptr);
      if (args->json) {
        nlohmann::json j = report::evaluation_json(scene, e);
        if (reference) j["against"] = args->against;
        j["options"] = report::metric_options_json(options);
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
