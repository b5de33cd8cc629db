// shapeproc synthesize EXEMPLAR -o out.svg --size ... [--method shape-process|ma-em|davison|ijiri]:
// the shape process (fit, then sample), the neighbourhood EM of Ma et al. 2011 or the region
// growing of Davison et al. 2018, through the same domain, chains, outputs and pictures.
#include <cmath>
#include <memory>

#include "libshapeproc/compare/neighbourhood_em.hpp"
#include "libshapeproc/compare/region_growing.hpp"
#include "libshapeproc/compare/seed_and_grow.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/io/graph_svg_writer.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/number_rows.hpp"
#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/flags.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

namespace {

// An orientation (flow) field from --orientation-field: none, a constant angle or a PNG.
compare::OrientationField orientation_field(const std::string& orientation,
                                            const geometry::Domain& domain) {
  if (orientation.empty()) return {};
  if (io::extension_of(orientation) == "png")
    return compare::OrientationField::map(
        std::make_shared<const geometry::Raster>(io::read_grayscale_png(orientation)),
        domain.box());
  const auto angle = io::parse_number_list(orientation);
  if (!angle || angle->size() != 1)
    throw core::UsageError("--orientation-field: expected an angle in degrees or a .png, got '" +
                           orientation + "'");
  return compare::OrientationField::constant((*angle)[0]);
}

// The neighbourhood EM's options (--method ma-em).
struct EmFlags {
  double rings = compare::EmOptions{}.rings;
  int k = compare::EmOptions{}.k;
  double alpha = compare::EmOptions{}.alpha;
  double lambda = compare::EmOptions{}.lambda;
  std::string samples = "auto";
  std::string initialisation = "patch-copy";
  std::string search = "k-coherence";
  std::string reconstruction = "rigid";
  std::string orientation;
  bool physics = false;
  int physics_steps = compare::kPhysicsSubSteps;

  // The options both neighbourhood methods (ma-em, davison) take.
  void add_shared_to(CLI::App& command) {
    command
        .add_option("--neighbourhood", rings,
                    "ma-em, davison: neighbourhood size in rings (1 to 3)")
        ->check(CLI::Range(0.25, 10.0))
        ->capture_default_str();
    command.add_option("--k", k, "ma-em, davison: k-coherence similarity set size")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    command
        .add_option("--alpha", alpha,
                    "ma-em, davison: weight of an attribute mismatch, in squared mean nearest "
                    "distances")
        ->check(non_negative_number())
        ->capture_default_str();
  }

  void add_to(CLI::App& command) {
    command
        .add_option("--lambda", lambda,
                    "ma-em: weight of the domain-shape term, in squared mean nearest distances")
        ->check(non_negative_number())
        ->capture_default_str();
    command
        .add_option("--samples-per-element", samples,
                    "ma-em: samples per element, 1 to 16, or auto (from each shape's elongation)")
        ->capture_default_str();
    command.add_option("--initialisation", initialisation, "ma-em: the starting output")
        ->check(CLI::IsMember({"patch-copy", "random-copy", "incremental-add"}))
        ->capture_default_str();
    command.add_option("--search", search, "ma-em: k-coherence or brute-force search")
        ->check(CLI::IsMember({"k-coherence", "brute-force"}))
        ->capture_default_str();
    command
        .add_option("--reconstruction", reconstruction,
                    "ma-em: how elements are rebuilt from their samples")
        ->check(CLI::IsMember({"rigid", "similarity", "tps", "tps-approx"}))
        ->capture_default_str();
    CLI::Option* flag =
        command.add_flag("--physics", physics,
                         "ma-em: interleave rigid-body steps (Box2D in 2D, Bullet in 3D) that push "
                         "interpenetrating elements apart");
    command
        .add_option("--physics-steps", physics_steps,
                    "ma-em: engine steps per EM iteration with --physics")
        ->check(CLI::Range(1, 1000))
        ->needs(flag)
        ->capture_default_str();
  }

  void add_orientation_to(CLI::App& command) {
    command.add_option("--orientation-field", orientation,
                       "ma-em, ijiri (2D): a constant angle in degrees, or a grayscale PNG "
                       "stretched over --size (grey g turns the exemplar's frame by 360 g "
                       "degrees); ijiri takes it with --rotation flow-field");
  }

  compare::EmOptions options(const geometry::Domain& domain, long long iterations) const {
    compare::EmOptions o;
    o.rings = rings;
    o.k = k;
    o.alpha = alpha;
    o.lambda = lambda;
    if (samples != "auto") {
      const auto n = io::parse_number_list(samples);
      if (!n || n->size() != 1 || (*n)[0] != std::floor((*n)[0]) || (*n)[0] < 1 ||
          (*n)[0] > compare::kMaxSamplesPerElement)
        throw core::UsageError("--samples-per-element: expected 1 to 16 or auto, got '" + samples +
                               "'");
      o.samples.per_element = static_cast<int>((*n)[0]);
    }
    o.initialisation = compare::parse_initialisation(initialisation);
    o.search = search == "brute-force" ? compare::SearchRule::brute_force
                                       : compare::SearchRule::k_coherence;
    o.reconstruction = compare::parse_reconstruction(reconstruction);
    o.physics_steps = physics ? physics_steps : 0;
    if (iterations > 10000) throw core::UsageError("--iterations: ma-em takes at most 10000");
    if (iterations > 0) o.iterations = static_cast<int>(iterations);
    o.orientation = orientation_field(orientation, domain);
    return o;
  }
};

// Region growing's options (--method davison); it shares --neighbourhood, --k and --alpha.
struct GrowthFlags {
  double ratio = compare::GrowthOptions{}.ratio;
  double bounding_radius = 0.0;
  bool no_optimise = false;
  std::string overlap;

  // --overlap, which ijiri takes too.
  void add_overlap_to(CLI::App& command) {
    command
        .add_option("--overlap", overlap,
                    "davison, ijiri: overlap test of new elements: bounding circles (spheres; "
                    "davison's default, as the paper), none (ijiri's default, as the paper) or "
                    "the shapes themselves (ijiri: turns then snap to 0.5 degrees)")
        ->check(CLI::IsMember({"circles", "shapes", "none"}));
  }

  void add_to(CLI::App& command) {
    command
        .add_option("--ratio", ratio,
                    "davison: a candidate that can grow is taken only within this ratio of the "
                    "best candidate's neighbourhood distance (> 1)")
        ->check(CLI::Range(1.0 + 1e-9, 1e6))
        ->capture_default_str();
    command
        .add_option("--bounding-radius", bounding_radius,
                    "davison: every element's bounding radius (default: half each exemplar "
                    "element's nearest distance, within its bounding circle)")
        ->check(non_negative_number());
    command.add_flag("--no-optimise", no_optimise,
                     "davison: grow without the least-squares relaxation of the front");
  }

  compare::GrowthOptions options(const EmFlags& shared) const {
    compare::GrowthOptions o;
    o.rings = shared.rings;
    o.k = shared.k;
    o.alpha = shared.alpha;
    o.ratio = ratio;
    o.bounding_radius = bounding_radius;
    o.optimise = !no_optimise;
    return o;
  }
};

// Seed-and-grow's options (--method ijiri).
struct IjiriFlags {
  std::string rotation = "none", flips, seeds, priority, weights = "1,1,100", show;
  bool no_relax = false;

  void add_to(CLI::App& command) {
    command
        .add_option("--rotation", rotation,
                    "ijiri: none (references keep their orientation), best (each match turned to "
                    "fit) or flow-field (turned by --orientation-field)")
        ->check(CLI::IsMember({"none", "best", "flow-field"}))
        ->capture_default_str();
    command.add_option("--edge-flips", flips,
                       "ijiri: file of exemplar edges to flip, one 'i j' pair of element indices "
                       "per line ('#' comments)");
    command.add_option("--seeds", seeds,
                       "ijiri: file of initial seed positions, one 'x y' per line (default: one "
                       "seed at the centre)");
    command.add_option("--priority", priority,
                       "ijiri: seed priorities by exemplar category, NAME=P,... (higher grows "
                       "first within 5 mean edge lengths)");
    command.add_option("--weights", weights, "ijiri: w1,w2,w3 of eq. 2 (distance, symbol, sub-id)")
        ->capture_default_str();
    command.add_flag("--no-relax", no_relax, "ijiri: grow without the relaxation of eq. 5");
    command.add_option("--show-connectivity", show,
                       "ijiri: also draw the exemplar's connectivity (after --edge-flips) to this "
                       ".svg, elements labelled by index, border elements hollow");
  }

  compare::SeedGrowthOptions options(const geometry::Scene& exemplar,
                                     const std::string& orientation, const std::string& overlap,
                                     const geometry::Domain& domain) const {
    compare::SeedGrowthOptions o;
    if (overlap == "circles")
      throw core::UsageError("--overlap circles: --method ijiri tests shapes or none");
    o.exact_overlap = overlap == "shapes";
    o.rotation = compare::parse_rotation_mode(rotation);
    o.field = orientation_field(orientation, domain);
    if (o.rotation == compare::RotationMode::flow_field && o.field.empty())
      throw core::UsageError("--rotation flow-field needs --orientation-field");
    if (o.rotation != compare::RotationMode::flow_field && !o.field.empty())
      throw core::UsageError(
          "--orientation-field: --method ijiri takes it with --rotation "
          "flow-field");
    const auto w = io::parse_number_list(weights);
    if (!w || w->size() != 3 || (*w)[0] < 0 || (*w)[1] < 0 || (*w)[2] < 0)
      throw core::UsageError("--weights: expected three numbers >= 0 (w1,w2,w3), got '" + weights +
                             "'");
    o.w1 = (*w)[0];
    o.w2 = (*w)[1];
    o.w3 = (*w)[2];
    o.relax = !no_relax;
    if (!flips.empty())
      for (const auto& row : io::read_number_rows(flips, 2)) {
        if (row[0] != std::floor(row[0]) || row[1] != std::floor(row[1]) || row[0] < 0 ||
            row[1] < 0 || row[0] >= 1e9 || row[1] >= 1e9)
          throw core::UsageError(flips + ": element indices must be whole numbers >= 0");
        o.flips.push_back({static_cast<int>(row[0]), static_cast<int>(row[1])});
      }
    if (!seeds.empty())
      for (const auto& row : io::read_number_rows(seeds, 2))
        o.seeds.emplace_back(row[0], row[1], 0.0);
    if (!priority.empty()) {
      o.priority.assign(exemplar.categories.size(), 0);
      for (const std::string& item : io::split(priority, ',')) {
        const auto equals = item.find('=');
        const auto value =
            equals == std::string::npos ? std::nullopt : io::parse_number(item.substr(equals + 1));
        if (!value || *value != std::floor(*value))
          throw core::UsageError("--priority: expected NAME=P with a whole P, got '" + item + "'");
        const std::string name(io::trim(item.substr(0, equals)));
        bool found = false;
        for (std::size_t c = 0; c < exemplar.categories.size(); ++c)
          if (exemplar.categories[c].name == name) {
            o.priority[c] = static_cast<int>(*value);
            found = true;
          }
        if (!found)
          throw core::UsageError("--priority: the exemplar has no category '" + name + "'");
      }
    }
    return o;
  }
};

// The exemplar's connectivity as a picture (--show-connectivity).
void show_connectivity(const compare::SeedGrowthExemplar& exemplar, const std::string& file) {
  std::vector<geometry::Vec3> nodes;
  std::vector<bool> open;
  for (std::size_t e = 0; e < exemplar.scene.elements.size(); ++e) {
    nodes.push_back(exemplar.domain.wrap(exemplar.scene.elements[e].position));
    open.push_back(!exemplar.connectivity.rings[e].closed);
  }
  std::vector<io::GraphEdge> edges;
  for (const auto& [first, offset] : compare::ring_edges(exemplar.connectivity))
    edges.push_back({first, offset});
  io::write_graph_svg(file, exemplar.scene.window, nodes, edges, open);
}

// The names of the options added to `command` since it had `before` of them.
std::vector<std::string> options_since(const CLI::App& command, std::size_t before) {
  std::vector<std::string> names;
  const auto all = command.get_options();
  for (std::size_t i = before; i < all.size(); ++i) names.push_back(all[i]->get_name());
  return names;
}

// Throws when an option of the other method was given.
void reject_options(const CLI::App& command, const std::vector<std::string>& names,
                    const std::string& method) {
  for (const std::string& name : names) {
    if (command.count(name) > 0) throw core::UsageError(name + " is for --method " + method);
  }
}

}  // namespace

void add_synthesize_command(CLI::App& app, Action& action,
                            const std::vector<std::string>& arguments) {
  struct SynthesizeArguments {
    std::string input, output, model, method = "shape-process";
    FitFlags fit;
    ReaderFlags reader;
    SampleFlags sample;
    EmFlags em;
    GrowthFlags growth;
    IjiriFlags ijiri;
    std::vector<std::string> fit_only, shared, em_only, growth_only, orientation, ijiri_only,
        growth_overlap;
  };
  auto args = std::make_shared<SynthesizeArguments>();
  CLI::App* command = app.add_subcommand(
      "synthesize",
      "Synthesise an output like an exemplar: fit a shape process and sample it, or "
      "run another method (--method)");
  command->add_option("EXEMPLAR", args->input, "input file")->required();
  command->add_option("-o,--output", args->output, "output (.svg, .obj, .ply, .csv)")->required();
  command
      ->add_option("--method", args->method,
                   "shape-process, ma-em (the neighbourhood EM of Ma et al. 2011), davison "
                   "(region growing, Davison et al. 2018) or ijiri (seed-and-grow, Ijiri et al. "
                   "2008)")
      ->check(CLI::IsMember({"shape-process", "ma-em", "davison", "ijiri"}))
      ->capture_default_str();
  std::size_t before = command->get_options().size();
  command->add_option("--model", args->model, "also write the fitted model (.json)");
  args->fit.add_to(*command);
  command
      ->add_option("--shift-probability", args->sample.shift_probability,
                   "share of steps that shift an element (0: birth-death only)")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  command
      ->add_option("--shift-radius", args->sample.shift_radius,
                   "largest shift (default: half the interaction range)")
      ->check(non_negative_number());
  command->add_option("--intensity", args->sample.intensity,
                      "2D intensity map: grayscale PNG stretched over --size, scales beta");
  args->fit_only = options_since(*command, before);
  before = command->get_options().size();
  args->em.add_shared_to(*command);
  args->shared = options_since(*command, before);
  before = command->get_options().size();
  args->em.add_to(*command);
  args->em_only = options_since(*command, before);
  before = command->get_options().size();
  args->growth.add_to(*command);
  args->growth_only = options_since(*command, before);
  before = command->get_options().size();
  args->em.add_orientation_to(*command);
  args->orientation = options_since(*command, before);
  before = command->get_options().size();
  args->ijiri.add_to(*command);
  args->ijiri_only = options_since(*command, before);
  before = command->get_options().size();
  args->growth.add_overlap_to(*command);
  args->growth_overlap = options_since(*command, before);
  args->reader.add_to(*command);
  args->sample.add_to(*command, /*sampler_options=*/false);
  command->callback([&action, args, arguments, command] {
    action = [args, arguments, command](std::ostream& out) {
      const bool em = args->method == "ma-em", growth = args->method == "davison";
      if (args->method != "shape-process")
        reject_options(*command, args->fit_only, "shape-process");
      if (!em) reject_options(*command, args->em_only, "ma-em");
      if (!growth) reject_options(*command, args->growth_only, "davison");
      const bool ijiri = args->method == "ijiri";
      if (!ijiri) reject_options(*command, args->ijiri_only, "ijiri");
      if (!em && !ijiri) reject_options(*command, args->orientation, "ma-em or ijiri");
      if (!growth && !ijiri) reject_options(*command, args->growth_overlap, "davison or ijiri");
      if (!em && !growth) reject_options(*command, args->shared, "ma-em or davison");
      if (!args->model.empty() && io::extension_of(args->model) != "json")
        throw core::UsageError(args->model + ": the model is written as .json");
      args->sample.check(args->output);
      args->reader.options();
      synthesis::SynthesisRecord record;
      record.command = "synthesize";
      record.arguments = arguments;
      record.inputs = {{"exemplar", args->input}};
      if (ijiri) {
        if (args->sample.iterations > 0)
          throw core::UsageError(
              "--iterations: --method ijiri grows until no seed is left; it takes no iteration "
              "count");
        const geometry::Scene exemplar = io::read_scene(args->input, args->reader.options());
        args->sample.check(args->output, exemplar.dimension);
        if (exemplar.dimension != 2)
          throw core::UsageError(args->input + ": --method ijiri grows 2D exemplars only");
        const geometry::Domain domain = args->sample.domain(exemplar.dimension);
        compare::SeedGrowthOptions options =
            args->ijiri.options(exemplar, args->em.orientation, args->growth.overlap, domain);
        args->sample.verbosity.stage("analysing the exemplar");
        const compare::SeedAndGrow method(
            exemplar, args->reader.tile ? geometry::Boundary::torus : geometry::Boundary::open,
            domain, std::move(options));
        if (!args->ijiri.show.empty()) {
          if (io::extension_of(args->ijiri.show) != "svg")
            throw core::UsageError("--show-connectivity: expected an .svg file, got '" +
                                   args->ijiri.show + "'");
          show_connectivity(method.exemplar(), args->ijiri.show);
          out << "wrote the connectivity to " << args->ijiri.show << '\n';
        }
        out << "seed-and-grow: " << exemplar.elements.size() << " exemplar elements, "
            << method.exemplar().references.size() << " with closed rings, mean edge "
            << core::format_number(method.exemplar().connectivity.mean_edge) << ' '
            << exemplar.units << '\n';
        if (!args->ijiri.flips.empty()) record.inputs.emplace_back("edge flips", args->ijiri.flips);
        if (!args->ijiri.seeds.empty()) record.inputs.emplace_back("seeds", args->ijiri.seeds);
        for (auto& pair : flatten_options("reader", args->reader.to_json()))
          record.options.push_back(std::move(pair));
        args->sample.verbosity.stage("growing");
        return args->sample.run(method, args->output, std::move(record), out);
      }
      if (growth) {
        if (args->sample.iterations > 0)
          throw core::UsageError(
              "--iterations: --method davison grows until the domain is full; it takes no "
              "iteration count");
        const geometry::Scene exemplar = io::read_scene(args->input, args->reader.options());
        args->sample.check(args->output, exemplar.dimension);
        const geometry::Domain domain = args->sample.domain(exemplar.dimension);
        args->sample.verbosity.stage("analysing the exemplar");
        const compare::RegionGrowing method(
            exemplar, args->reader.tile ? geometry::Boundary::torus : geometry::Boundary::open,
            domain, args->growth.options(args->em));
        out << "region growing: " << exemplar.elements.size()
            << " exemplar elements, neighbourhood radius "
            << core::format_number(method.exemplar().em.radius) << ' ' << exemplar.units << '\n';
        for (auto& pair : flatten_options("reader", args->reader.to_json()))
          record.options.push_back(std::move(pair));
        args->sample.verbosity.stage("growing");
        return args->sample.run(method, args->output, std::move(record), out);
      }
      if (em) {
        const geometry::Scene exemplar = io::read_scene(args->input, args->reader.options());
        args->sample.check(args->output, exemplar.dimension);
        const geometry::Domain domain = args->sample.domain(exemplar.dimension);
        const compare::EmOptions options = args->em.options(domain, args->sample.iterations);
        args->sample.verbosity.stage("analysing the exemplar");
        const compare::NeighbourhoodEm method(
            exemplar, args->reader.tile ? geometry::Boundary::torus : geometry::Boundary::open,
            domain, options);
        out << "neighbourhood EM: " << exemplar.elements.size() << " exemplar elements, "
            << method.exemplar().samples.size() << " samples, radius "
            << core::format_number(method.exemplar().radius) << ' ' << exemplar.units << '\n';
        for (auto& pair : flatten_options("reader", args->reader.to_json()))
          record.options.push_back(std::move(pair));
        args->sample.verbosity.stage("synthesising");
        return args->sample.run(method, args->output, std::move(record), out);
      }
      args->fit.options(args->reader);  // its own checks, before reading or fitting anything
      const fit::FitResult fitted =
          fit_exemplar(args->input, args->fit, args->reader, arguments, args->sample.verbosity);
      if (!args->model.empty()) io::write_model(fitted.model, args->model);
      print_model_brief(fitted.model, out);
      if (!args->model.empty()) record.inputs.emplace_back("model", args->model);
      record.options = flatten_options("fit", args->fit.to_json());
      for (auto& pair : flatten_options("reader", args->reader.to_json()))
        record.options.push_back(std::move(pair));
      args->sample.verbosity.stage("sampling");
      return args->sample.run(fitted.model, args->output, std::move(record), out);
    };
  });
}

}  // namespace shapeproc::cli
