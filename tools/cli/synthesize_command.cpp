// shapeproc synthesize EXEMPLAR -o out.svg --size ... [--method shape-process|ma-em|davison|ijiri]:
// the shape process (fit, then sample), the neighbourhood EM of Ma et al. 2011, the region growing
// of Davison et al. 2018 or the seed-and-grow of Ijiri et al. 2008, through the same domain,
// chains, outputs and pictures. The methods' own flags are in method_flags.
#include <filesystem>
#include <memory>
#include <system_error>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/methods/davison2018/region_growing.hpp"
#include "libshapeproc/methods/hybrid_synthesis.hpp"
#include "libshapeproc/methods/ijiri2008/seed_and_grow.hpp"
#include "libshapeproc/methods/ma2011/neighbourhood_em.hpp"
#include "libshapeproc/methods/tiled_exemplar.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/flags.hpp"
#include "tools/cli/method_flags.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

namespace {

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

// The reader's options, in the outputs' record.
void record_reader(const ReaderFlags& reader, synthesis::SynthesisRecord& record) {
  for (auto& pair : flatten_options("reader", reader.to_json()))
    record.options.push_back(std::move(pair));
}

struct SynthesizeArguments {
  std::string input, output, model, method = "shape-process", start_from = "ma-em", start = "auto";
  FitFlags fit;
  ReaderFlags reader;
  SampleFlags sample;
  EmFlags em;
  GrowthFlags growth;
  IjiriFlags ijiri;
  std::vector<std::string> fit_only, shared, em_only, growth_only, orientation, ijiri_only,
      growth_overlap;
};

// --method hybrid: the start method's output, then the shape-process sampler at `model`.
int run_hybrid(const SynthesizeArguments& args, const model::ShapeProcessModel& model,
               synthesis::SynthesisRecord record, std::ostream& out) {
  const geometry::Scene exemplar = io::read_scene(args.input, args.reader.options());
  const geometry::Boundary boundary = args.reader.boundary();
  const geometry::Domain domain = args.sample.domain(exemplar.dimension);
  std::unique_ptr<synthesis::Synthesizer> start;
  if (args.start_from == "ma-em") {
    start = std::make_unique<methods::NeighbourhoodEm>(exemplar, boundary, domain,
                                                       args.em.options(domain, 0));
  } else if (args.start_from == "davison") {
    start = std::make_unique<methods::RegionGrowing>(exemplar, boundary, domain,
                                                     args.growth.options(args.em));
  } else {
    if (exemplar.dimension != 2)
      throw core::UsageError(args.input + ": --start-from ijiri grows 2D exemplars only");
    start = std::make_unique<methods::SeedAndGrow>(exemplar, boundary, domain,
                                                   args.ijiri.options(exemplar, "", "", domain));
  }
  const methods::HybridSynthesis method(std::move(start), model, domain,
                                        args.sample.sampler_options());
  out << "hybrid: " << args.start_from << "'s output, then the shape-process sampler\n";
  args.sample.verbosity.stage("synthesising");
  return args.sample.run(method, args.output, std::move(record), out);
}

// The exemplar, with the output's name and the resource budget checked against it.
geometry::Scene read_checked_exemplar(SynthesizeArguments& args) {
  geometry::Scene exemplar = io::read_scene(args.input, args.reader.options());
  args.sample.set_exemplar(exemplar);
  args.sample.check(args.output, exemplar.dimension);
  args.sample.check_budget(exemplar);
  return exemplar;
}

// --method tile: the exemplar repeated over the output.
int run_tile(SynthesizeArguments& args, synthesis::SynthesisRecord record, std::ostream& out) {
  const geometry::Scene exemplar = read_checked_exemplar(args);
  const methods::TiledExemplar method(exemplar, args.sample.domain(exemplar.dimension));
  out << "tile: the exemplar repeated over the output (the baseline: a copy, no novelty)\n";
  record_reader(args.reader, record);
  return args.sample.run(method, args.output, std::move(record), out);
}

// --method ijiri: seed-and-grow.
int run_ijiri(SynthesizeArguments& args, synthesis::SynthesisRecord record, std::ostream& out) {
  if (args.sample.iterations > 0)
    throw core::UsageError(
        "--iterations: --method ijiri grows until no seed is left; it takes no iteration "
        "count");
  const geometry::Scene exemplar = read_checked_exemplar(args);
  if (exemplar.dimension != 2)
    throw core::UsageError(args.input + ": --method ijiri grows 2D exemplars only");
  const geometry::Domain domain = args.sample.domain(exemplar.dimension);
  methods::SeedGrowthOptions options =
      args.ijiri.options(exemplar, args.em.orientation, args.growth.overlap, domain);
  args.sample.verbosity.stage("analysing the exemplar");
  const methods::SeedAndGrow method(exemplar, args.reader.boundary(), domain, std::move(options));
  if (!args.ijiri.show.empty()) {
    if (io::extension_of(args.ijiri.show) != "svg")
      throw core::UsageError("--show-connectivity: expected an .svg file, got '" + args.ijiri.show +
                             "'");
    show_connectivity(method.exemplar(), args.ijiri.show);
    out << "wrote the connectivity to " << args.ijiri.show << '\n';
  }
  out << "seed-and-grow: " << exemplar.elements.size() << " exemplar elements, "
      << method.exemplar().references.size() << " with closed rings, mean edge "
      << core::format_number(method.exemplar().connectivity.mean_edge) << ' ' << exemplar.units
      << '\n';
  if (!args.ijiri.flips.empty()) record.inputs.emplace_back("edge flips", args.ijiri.flips);
  if (!args.ijiri.seeds.empty()) record.inputs.emplace_back("seeds", args.ijiri.seeds);
  record_reader(args.reader, record);
  args.sample.verbosity.stage("growing");
  return args.sample.run(method, args.output, std::move(record), out);
}

// --method davison: region growing, with an optional palette.
int run_davison(SynthesizeArguments& args, synthesis::SynthesisRecord record, std::ostream& out) {
  if (args.sample.iterations > 0)
    throw core::UsageError(
        "--iterations: --method davison grows until the domain is full; it takes no "
        "iteration count");
  const geometry::Boundary boundary = args.reader.boundary();
  std::vector<methods::GrowthSource> palette;
  palette.reserve(2);  // `exemplar` stays valid
  palette.push_back({io::read_scene(args.input, args.reader.options()), boundary});
  const geometry::Scene& exemplar = palette.front().scene;
  args.sample.set_exemplar(exemplar);
  args.sample.check(args.output, exemplar.dimension);
  args.sample.check_budget(exemplar);
  if (args.growth.palette.empty() &&
      (args.growth.palette_rings > 0 || args.growth.palette_bounding_radius >= 0))
    throw core::UsageError(
        "--palette-neighbourhood, --palette-bounding-radius: they need --palette");
  if (!args.growth.palette.empty()) {
    palette.push_back({io::read_scene(args.growth.palette, args.reader.options()), boundary,
                       args.growth.palette_rings, args.growth.palette_bounding_radius});
    if (palette.back().scene.dimension != exemplar.dimension)
      throw core::UsageError(args.growth.palette + ": --palette is " +
                             std::to_string(palette.back().scene.dimension) +
                             "D but the exemplar is " + std::to_string(exemplar.dimension) + "D");
    record.inputs.emplace_back("palette", args.growth.palette);
  }
  const geometry::Domain domain = args.sample.domain(exemplar.dimension);
  args.sample.verbosity.stage("analysing the exemplar");
  const methods::RegionGrowing method(palette, domain, args.growth.options(args.em));
  const methods::GrowthExemplar& grown = method.exemplar();
  for (std::size_t s = 0, part = 0; s < grown.part.size(); ++s) {
    if (static_cast<std::size_t>(grown.part[s]) != part) continue;
    const std::size_t count = palette[part].scene.elements.size();
    out << (part == 0 ? "region growing: " : "palette: ") << count
        << " exemplar elements, neighbourhood radius " << core::format_number(grown.reach[s]) << ' '
        << palette[part].scene.units << '\n';
    ++part;
  }
  record_reader(args.reader, record);
  args.sample.verbosity.stage("growing");
  return args.sample.run(method, args.output, std::move(record), out);
}

// --method ma-em: the neighbourhood EM.
int run_em(SynthesizeArguments& args, synthesis::SynthesisRecord record, std::ostream& out) {
  const geometry::Scene exemplar = read_checked_exemplar(args);
  const geometry::Domain domain = args.sample.domain(exemplar.dimension);
  const methods::EmOptions options = args.em.options(domain, args.sample.iterations);
  args.sample.verbosity.stage("analysing the exemplar");
  const methods::NeighbourhoodEm method(exemplar, args.reader.boundary(), domain, options);
  out << "neighbourhood EM: " << exemplar.elements.size() << " exemplar elements, "
      << method.exemplar().samples.size() << " samples, radius "
      << core::format_number(method.exemplar().radius) << ' ' << exemplar.units << '\n';
  record_reader(args.reader, record);
  args.sample.verbosity.stage("synthesising");
  return args.sample.run(method, args.output, std::move(record), out);
}

// --method shape-process or hybrid: fit, then sample (a hybrid from another method's output).
int run_shape_process(SynthesizeArguments& args, const std::vector<std::string>& arguments,
                      synthesis::SynthesisRecord record, std::ostream& out) {
  const bool hybrid = args.method == "hybrid";
  args.fit.options(args.reader);  // its own checks, before reading or fitting anything
  args.fit.threads = args.sample.threads;
  geometry::Scene exemplar;
  const fit::FitResult fitted =
      fit_exemplar(args.input, args.fit, args.reader, arguments, args.sample.verbosity,
                   args.sample.budget.budget(), &exemplar, [&](const geometry::Scene& read) {
                     args.sample.set_exemplar(read);
                     args.sample.check_budget(read);
                   });
  if (!args.model.empty()) io::write_model(fitted.model, args.model);
  print_model_brief(fitted.model, out);
  if (!args.model.empty()) record.inputs.emplace_back("model", args.model);
  record.options = flatten_options("fit", args.fit.to_json());
  record_reader(args.reader, record);
  if (hybrid) return run_hybrid(args, fitted.model, std::move(record), out);
  const bool at_exemplar = args.start == "exemplar";
  record.options.emplace_back("start", at_exemplar ? "exemplar" : "empty");
  args.sample.verbosity.stage("sampling");
  return args.sample.run(fitted.model, args.output, std::move(record), out,
                         at_exemplar ? &exemplar : nullptr);
}

// The options of the other methods, each group remembered so that a method refuses the others'.
void add_method_options(CLI::App& command, SynthesizeArguments& args) {
  // The names of the options that `add` adds.
  const auto group = [&command](const auto& add) {
    const std::size_t before = command.get_options().size();
    add();
    return options_since(command, before);
  };
  args.shared = group([&] { args.em.add_shared_to(command); });
  args.em_only = group([&] { args.em.add_to(command); });
  args.growth_only = group([&] { args.growth.add_to(command); });
  args.orientation = group([&] { args.em.add_orientation_to(command); });
  args.ijiri_only = group([&] { args.ijiri.add_to(command); });
  args.growth_overlap = group([&] { args.growth.add_overlap_to(command); });
}

// Options given for another method than --method are refused, naming the method they are for;
// --model must be a new .json file.
void check_method_options(const CLI::App& command, const SynthesizeArguments& args,
                          const CLI::Option& start_from, const CLI::Option& start) {
  const bool em = args.method == "ma-em", growth = args.method == "davison";
  const bool hybrid = args.method == "hybrid", ijiri = args.method == "ijiri";
  if (args.method != "shape-process" && !hybrid)
    reject_options(command, args.fit_only, "shape-process or hybrid");
  if (!hybrid && start_from.count() > 0)
    throw core::UsageError("--start-from is for --method hybrid");
  if (hybrid && start.count() > 0)
    throw core::UsageError(
        "--start is for --method shape-process (a hybrid starts from --start-from's output)");
  if (!em) reject_options(command, args.em_only, "ma-em");
  if (!growth) reject_options(command, args.growth_only, "davison");
  if (!ijiri) reject_options(command, args.ijiri_only, "ijiri");
  if (!em && !ijiri) reject_options(command, args.orientation, "ma-em or ijiri");
  if (!growth && !ijiri) reject_options(command, args.growth_overlap, "davison or ijiri");
  if (!em && !growth) reject_options(command, args.shared, "ma-em or davison");
  if (!args.model.empty() && io::extension_of(args.model) != "json")
    throw core::UsageError(args.model + ": the model is written as .json");
  std::error_code missing;  // a name the system refuses (too long) is no existing file
  if (!args.model.empty() && !args.sample.force && std::filesystem::exists(args.model, missing))
    throw core::UsageError(args.model +
                           " exists: give --force to overwrite, or another "
                           "--model");
}

}  // namespace

void add_synthesize_command(CLI::App& app, Action& action,
                            const std::vector<std::string>& arguments) {
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
                   "(region growing, Davison et al. 2018), ijiri (seed-and-grow, Ijiri et al. "
                   "2008), hybrid (--start-from's output, then the shape-process sampler at the "
                   "fitted model) or tile (the exemplar repeated: the baseline every method is "
                   "compared with)")
      ->check(CLI::IsMember({"shape-process", "ma-em", "davison", "ijiri", "hybrid", "tile"}))
      ->capture_default_str();
  CLI::Option* start_from =
      command
          ->add_option("--start-from", args->start_from,
                       "hybrid: the method whose output the sampler starts from (its default "
                       "options)")
          ->check(CLI::IsMember({"ma-em", "davison", "ijiri"}))
          ->capture_default_str();
  const std::size_t before = command->get_options().size();
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
  CLI::Option* start =
      command
          ->add_option("--start", args->start,
                       "shape-process: where each chain starts: empty (with the compressing "
                       "burn-in where the model's fit used it), or exemplar (the exemplar tiled "
                       "over the output: the output begins as a copy; auto is empty)")
          ->check(CLI::IsMember({"auto", "exemplar", "empty"}))
          ->capture_default_str();
  args->fit_only = options_since(*command, before);
  add_method_options(*command, *args);
  args->reader.add_to(*command);
  args->sample.add_to(*command, /*sampler_options=*/false, /*exemplar_multiples=*/true);
  command->callback([&action, args, arguments, command, start_from, start] {
    action = [args, arguments, command, start_from, start](std::ostream& out) {
      check_method_options(*command, *args, *start_from, *start);
      args->sample.check(args->output);
      args->reader.options();
      synthesis::SynthesisRecord record;
      record.command = "synthesize";
      record.arguments = arguments;
      record.inputs = {{"exemplar", args->input}};
      if (args->method == "tile") return run_tile(*args, std::move(record), out);
      if (args->method == "ijiri") return run_ijiri(*args, std::move(record), out);
      if (args->method == "davison") return run_davison(*args, std::move(record), out);
      if (args->method == "ma-em") return run_em(*args, std::move(record), out);
      return run_shape_process(*args, arguments, std::move(record), out);
    };
  });
}

}  // namespace shapeproc::cli
