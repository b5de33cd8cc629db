// shapeproc synthesize EXEMPLAR -o out.svg --size ... [--method shape-process|ma-em|davison|ijiri]:
// the shape process (fit, then sample), the neighbourhood EM of Ma et al. 2011, the region growing
// of Davison et al. 2018 or the seed-and-grow of Ijiri et al. 2008, through the same domain,
// chains, outputs and pictures. The methods' own flags are in method_flags.
#include "tools/cli/synthesize_command.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/core/interruption.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/methods/synthesizer_factory.hpp"
#include "libshapeproc/pipeline/synthesis_run.hpp"
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

// The exemplar, with the output's name and size checked against it.
geometry::Scene read_checked_exemplar(SynthesizeArguments& args) {
  args.sample.verbosity.stage("reading " + args.input);
  geometry::Scene exemplar = io::read_scene(args.input, args.reader.options());
  args.sample.set_exemplar(exemplar);
  args.sample.check(args.output, exemplar.dimension);
  return exemplar;
}

// Davison's palette (--palette): the second exemplar, read with the first's reader options.
std::vector<methods::GrowthSource> read_palette(const SynthesizeArguments& args,
                                                const geometry::Scene& exemplar) {
  if (args.growth.palette.empty() &&
      (args.growth.palette_rings > 0 || args.growth.palette_bounding_radius >= 0))
    throw core::UsageError(
        "--palette-neighbourhood, --palette-bounding-radius: they need --palette");
  if (args.growth.palette.empty()) return {};
  std::vector<methods::GrowthSource> palette;
  palette.push_back({io::read_scene(args.growth.palette, args.reader.options()),
                     args.reader.boundary(), args.growth.palette_rings,
                     args.growth.palette_bounding_radius});
  if (palette.back().scene.dimension != exemplar.dimension)
    throw core::UsageError(args.growth.palette + ": --palette is " +
                           std::to_string(palette.back().scene.dimension) +
                           "D but the exemplar is " + std::to_string(exemplar.dimension) + "D");
  return palette;
}

// The library's options of the method and, for a hybrid, of its start, from the flags.
methods::MethodOptions method_options(const SynthesizeArguments& args, methods::Method method,
                                      const geometry::Scene& exemplar,
                                      const geometry::Domain& domain) {
  methods::MethodOptions options;
  const bool hybrid = method == methods::Method::hybrid;
  const methods::Method uses = hybrid ? *methods::method_from_name(args.start_from) : method;
  if (hybrid) options.start_from = uses;
  if (uses == methods::Method::ma_em)
    options.em = args.em.options(domain, hybrid ? 0 : args.sample.iterations);
  if (uses == methods::Method::davison) {
    options.growth = args.growth.options(args.em);
    options.palette = read_palette(args, exemplar);
  }
  if (uses == methods::Method::ijiri) {
    if (exemplar.dimension != 2)
      throw core::UsageError(args.input + (hybrid ? ": --start-from ijiri" : ": --method ijiri") +
                             " grows 2D exemplars only");
    options.ijiri = args.ijiri.options(exemplar, args.em.orientation, args.growth.overlap, domain);
  }
  if (hybrid) options.sampler = args.sample.sampler_options();
  return options;
}

// The inputs beyond the exemplar, in the outputs' record.
void record_method_inputs(const SynthesizeArguments& args, methods::Method method,
                          synthesis::SynthesisRecord& record) {
  if (method == methods::Method::ijiri) {
    if (!args.ijiri.flips.empty()) record.inputs.emplace_back("edge flips", args.ijiri.flips);
    if (!args.ijiri.seeds.empty()) record.inputs.emplace_back("seeds", args.ijiri.seeds);
  }
  if (method == methods::Method::davison && !args.growth.palette.empty())
    record.inputs.emplace_back("palette", args.growth.palette);
  record_reader(args.reader, record);
}

// What the method shows before its chains run: its connectivity (ijiri's --show-connectivity),
// what it learnt, and the run's warnings.
void show_ready(const SynthesizeArguments& args, methods::Method method,
                const synthesis::Synthesizer& synthesizer, const pipeline::SynthesisRun& so_far,
                std::ostream& out) {
  if (method == methods::Method::ijiri && !args.ijiri.show.empty()) {
    show_connectivity(dynamic_cast<const methods::SeedAndGrow&>(synthesizer).exemplar(),
                      args.ijiri.show);
    out << "wrote the connectivity to " << args.ijiri.show << '\n';
  }
  print_ready(so_far, out);
  if (method == methods::Method::hybrid)
    out << "hybrid: " << args.start_from << "'s output, then the shape-process sampler\n";
  const bool grows = method == methods::Method::ijiri || method == methods::Method::davison;
  if (method != methods::Method::tile)
    args.sample.verbosity.stage(method == methods::Method::shape_process ? "sampling"
                                : grows                                  ? "growing"
                                                                         : "synthesising");
}

// The fit of the shape process and the hybrid: its options from the flags, with progress; once
// done, its record completed, the model written (--model) and shown.
void request_fit(SynthesizeArguments& args, const std::vector<std::string>& arguments,
                 FitProgress& progress, pipeline::SynthesisRequest& request,
                 synthesis::SynthesisRecord& record, std::ostream& out) {
  request.fit = args.fit.exemplar_options(args.reader);
  progress.attach(request.fit);
  request.fitted = [&args, &arguments, &progress, &out](fit::ExemplarFit& fit) {
    progress.finish();
    args.fit.record(fit.result.model, args.input, args.reader, arguments);
    if (!args.model.empty()) io::write_model(fit.result.model, args.model);
    print_model_brief(fit.result.model, out);
  };
  if (!args.model.empty()) record.inputs.emplace_back("model", args.model);
  record.options = flatten_options("fit", args.fit.to_json());
  request.start_at_exemplar = args.start == "exemplar";
}

// Every method, through the library's synthesis (pipeline/synthesis_run.hpp): the shape process
// and the hybrid fitted first; the outputs written.
int run_method(SynthesizeArguments& args, const std::vector<std::string>& arguments,
               synthesis::SynthesisRecord record, std::ostream& out) {
  const methods::Method method = *methods::method_from_name(args.method);
  const bool fits = method == methods::Method::shape_process || method == methods::Method::hybrid;
  const bool grows = method == methods::Method::ijiri || method == methods::Method::davison;
  if (grows && args.sample.iterations > 0)
    throw core::UsageError("--iterations: --method " + args.method +
                           (method == methods::Method::ijiri
                                ? " grows until no seed is left; it takes no iteration count"
                                : " grows until the domain is full; it takes no iteration count"));
  if (!args.ijiri.show.empty() && io::extension_of(args.ijiri.show) != "svg")
    throw core::UsageError("--show-connectivity: expected an .svg file, got '" + args.ijiri.show +
                           "'");
  if (fits) {
    args.fit.options(args.reader);  // its own checks, before reading or fitting anything
    args.fit.threads = args.sample.threads;
  }
  const geometry::Scene exemplar = read_checked_exemplar(args);
  const geometry::Domain domain = args.sample.domain(exemplar.dimension);
  pipeline::SynthesisRequest request;
  request.method = method;
  request.source = args.input;
  if (method != methods::Method::shape_process)
    request.options = method_options(args, method, exemplar, domain);
  FitProgress progress(args.sample.verbosity);
  if (fits) request_fit(args, arguments, progress, request, record, out);
  record_method_inputs(args, method, record);
  if (method == methods::Method::shape_process)
    record.options.emplace_back("start", request.start_at_exemplar ? "exemplar" : "empty");
  if (!fits && method != methods::Method::tile)
    args.sample.verbosity.stage("analysing the exemplar");
  // Ctrl-C during the chains stops them and nothing is written; during the fit it ends the run at
  // once, as before any other long stage.
  std::optional<core::CancellableSection> interrupt;
  ProgressBar bar(method == methods::Method::shape_process ? "sampling" : "synthesising",
                  args.sample.verbosity.show_progress());
  request.sample =
      args.sample.sampling_request(std::move(record), bar, core::CancellableSection::flag());
  request.sample.ready = [&](const synthesis::Synthesizer& synthesizer,
                             const pipeline::SynthesisRun& so_far) {
    show_ready(args, method, synthesizer, so_far, out);
    interrupt.emplace();
  };
  const pipeline::SynthesisRun run =
      pipeline::synthesize(exemplar, args.reader.boundary(), domain, request);
  bar.finish();
  return args.sample.write(run, args.output, out);
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
      return run_synthesize(*args, arguments, out);
    };
  });
}

int run_synthesize(SynthesizeArguments& args, const std::vector<std::string>& arguments,
                   std::ostream& out) {
  args.sample.check(args.output);
  args.reader.options();
  synthesis::SynthesisRecord record;
  record.command = "synthesize";
  record.arguments = arguments;
  record.inputs = {{"exemplar", args.input}};
  return run_method(args, arguments, std::move(record), out);
}

}  // namespace shapeproc::cli
