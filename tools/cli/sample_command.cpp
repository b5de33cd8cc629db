// shapeproc sample model.json -o out.svg --size W,H[,D]: birth-death Metropolis-Hastings; and
// the chains' runner and output writer every synthesis method's command shares.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/core/interruption.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/io/domain_io.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/pipeline/synthesis_run.hpp"
#include "libshapeproc/render/raster.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/output_check.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/distributed_sample.hpp"
#include "tools/cli/flags.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

namespace {

// out.svg → out-2.svg for chain 2 of several; unchanged for a single chain.
std::string suffixed(const std::string& path, int chain, int chains) {
  if (chains <= 1 || path.empty()) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() /
          (p.stem().string() + "-" + std::to_string(chain + 1) + p.extension().string()))
      .string();
}

void write_trace(const std::string& file, const synthesis::SynthesisResult& result) {
  core::write_file_atomically(file, [&](std::ostream& f) {
    f << "# shapeproc " << result.record.command << ' ' << result.record.method << " seed "
      << result.record.seed << " chain " << result.record.chain
      << (result.record.method == "shape-process"    ? "\nstep,elements,log_density\n"
          : result.record.method == "region-growing" ? "\nround,elements,energy\n"
                                                     : "\niteration,elements,energy\n");
    for (const auto& t : result.trace)
      f << t.step << ',' << t.elements << ',' << core::format_number(t.log_density) << '\n';
  });
}

// The PNG's text chunks: what made it, so a picture found alone still says its seed and command.
std::vector<std::pair<std::string, std::string>> png_text(
    const synthesis::SynthesisRecord& record) {
  return {
      {"Software", std::string("shapeproc ") + SHAPEPROC_VERSION},
      {"Comment", "seed " + std::to_string(record.chain_seed) +
                      (record.chains > 1 ? " (chain " + std::to_string(record.chain) +
                                               " of run seed " + std::to_string(record.seed) + ")"
                                         : std::string())},
      {"Source", command_line(record.arguments)}};
}

}  // namespace

void SampleFlags::add_to(CLI::App& command, bool sampler_options, bool multiples) {
  exemplar_multiples = multiples;
  command
      .add_option("--size", size,
                  multiples ? "domain W,H (2D) or W,H,D (3D), in the exemplar's units, or as "
                              "multiples of its window: 3W,3H"
                            : "domain W,H (2D) or W,H,D (3D), in the model's units")
      ->required();
  command.add_option("--domain", domain_file,
                     "2D domain shape: an SVG (its filled shapes) or a grayscale PNG mask (white = "
                     "inside), stretched over --size");
  command
      .add_option(
          "--iterations", iterations,
          "steps per chain (default: until the element count is stationary, see docs/sample.md); "
          "ma-em: EM iterations (default 10)")
      ->check(non_negative_number());
  if (sampler_options) {
    command.add_option(
        "--intensity", intensity,
        "2D intensity map: grayscale PNG stretched over --size, scales beta (white = 1)");
    command
        .add_option("--shift-probability", shift_probability,
                    "share of steps that shift an element (0: birth-death only)")
        ->check(CLI::Range(0.0, 0.95))
        ->capture_default_str();
    command
        .add_option("--shift-radius", shift_radius,
                    "largest shift (default: half the interaction range)")
        ->check(non_negative_number());
    command
        .add_option("--decompose", decompose,
                    "sample each output in parallel cells (domain decomposition, docs/sample.md): "
                    "on, off, or auto (on for outputs of 10,000 elements or more)")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str();
  }
  command.add_option("--seed", seed, "random seed")->capture_default_str();
  command.add_option("--chains", chains, "independent chains; outputs get -1, -2, ... suffixes")
      ->check(CLI::Range(1, 1000));
  command
      .add_option("--threads", threads,
                  "threads for the chains, and for the cells of each output when decomposed "
                  "(default: one per core; outputs do not depend on them)")
      ->check(CLI::Range(0, 256));
  command.add_flag("--force", force, "overwrite outputs that exist (refused otherwise)");
  command
      .add_option("--boundary", boundary,
                  "torus (periodic; default for plain rectangles and boxes) or open (default with "
                  "--domain)")
      ->check(CLI::IsMember({"torus", "open"}));
  command.add_option("--trace", trace,
                     "write element count and log density every 100 steps (every 1/1000 of the "
                     "steps with --iterations) to this .csv");
  command.add_option("--png", png, "also render the output to this PNG");
  command
      .add_option("--png-scale", png_scale,
                  "pixels per unit length of the PNG (default: 800 pixels along the longer side)")
      ->check(positive_number());
  verbosity.add_to(command);
  budget.add_to(command);
}

std::vector<std::string> SampleFlags::files_written(const std::string& output) const {
  std::vector<std::string> files;
  for (int c = 0; c < chains; ++c) {
    const std::string file = suffixed(output, c, chains);
    files.push_back(file);
    if (io::extension_of(file) == "csv") files.push_back(file + ".json");
    if (!png.empty()) files.push_back(suffixed(png, c, chains));
    if (!trace.empty()) files.push_back(suffixed(trace, c, chains));
  }
  return files;
}

void SampleFlags::check(const std::string& output, int dimension) const {
  // Before the exemplar is read, multiples are checked for their syntax only.
  const geometry::Box3 unit(geometry::Vec3::Zero(), geometry::Vec3::Ones());
  const geometry::Box3* window = exemplar_window      ? &*exemplar_window
                                 : exemplar_multiples ? &unit
                                                      : nullptr;
  const auto sizes = io::parse_size(size, window);
  const bool count_ok = sizes && (dimension > 0 ? static_cast<int>(sizes->size()) == dimension
                                                : sizes->size() == 2 || sizes->size() == 3);
  if (!count_ok || !std::all_of(sizes->begin(), sizes->end(),
                                [](double v) { return v > 0 && std::isfinite(v); })) {
    const std::string expected = dimension == 2   ? "W,H"
                                 : dimension == 3 ? "W,H,D"
                                                  : "W,H (2D) or W,H,D (3D)";
    throw core::UsageError(
        "--size: expected " + expected + " (positive)" +
        (exemplar_multiples ? std::string(", or multiples of the exemplar's window such as 3W,3H")
                            : std::string()) +
        (dimension > 0 ? " for a " + std::to_string(dimension) + "D model" : std::string()) +
        ", got '" + size + "'");
  }
  if (iterations > kMaxIterations) {
    throw core::UsageError("--iterations: at most " + std::to_string(kMaxIterations) +
                           " (hours of sampling), got " + std::to_string(iterations));
  }
  check_output_extension(output, "-o");
  if (!png.empty() && io::extension_of(png) != "png")
    throw core::UsageError("--png: expected a .png file, got '" + png + "'");
  if (!trace.empty() && io::extension_of(trace) != "csv")
    throw core::UsageError("--trace: expected a .csv file, got '" + trace + "'");
  for (const std::string& file : {output, png, trace}) {
    if (!file.empty()) core::check_writable(file);
  }
  // No file written twice by one run (a chain's output over another's, -o and --png alike), and
  // none that exists overwritten without --force.
  std::vector<std::string> files = files_written(output);
  std::vector<std::string> sorted = files;
  std::sort(sorted.begin(), sorted.end());
  if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
    throw core::UsageError("the run would write " + *twice +
                           " twice: give -o, --png and --trace "
                           "different names");
  if (!force) {
    int existing = 0;
    std::string first;
    for (const std::string& file : files) {
      std::error_code error;  // a name the system refuses (too long) is no existing file
      if (!std::filesystem::exists(file, error)) continue;
      if (existing++ == 0) first = file;
    }
    if (existing > 0)
      throw core::UsageError(
          first + " exists" +
          (existing > 1 ? " (and " + std::to_string(existing - 1) + " more of this run's outputs)"
                        : std::string()) +
          ": give --force to overwrite, or another -o");
  }
  if (boundary == "torus" && !domain_file.empty())
    throw core::UsageError(
        "--boundary torus needs a rectangular domain: drop --domain or use --boundary open");
  if (sizes->size() == 3 && (!domain_file.empty() || !intensity.empty()))
    throw core::UsageError("--domain and --intensity are for 2D models");
  if (!domain_file.empty() && io::extension_of(domain_file) != "svg" &&
      io::extension_of(domain_file) != "png") {
    throw core::UsageError("--domain: expected an .svg (filled shapes) or a .png mask, got '" +
                           domain_file + "'");
  }
  if (!intensity.empty() && io::extension_of(intensity) != "png") {
    throw core::UsageError("--intensity: expected a grayscale .png, got '" + intensity + "'");
  }
  for (const std::string* file : {&domain_file, &intensity}) {
    if (!file->empty() && !std::filesystem::is_regular_file(*file))
      throw core::InputError(*file, 0, "no such file");
  }
}

geometry::Domain SampleFlags::domain(int dimension) const {
  io::DomainFiles files;
  files.size = *io::parse_size(size, exemplar_window ? &*exemplar_window : nullptr);
  files.boundary = boundary;
  files.mask = domain_file;
  files.intensity = intensity;
  return io::read_domain(files, dimension);
}

void print_ready(const pipeline::SynthesisRun& so_far, std::ostream& out) {
  for (const std::string& line : so_far.described) out << line << '\n';
  for (const std::string& line : so_far.warnings)
    out << "warning: " << core::name_options(line, flag_for) << '\n';
}

pipeline::SamplingRequest SampleFlags::sampling_request(synthesis::SynthesisRecord record,
                                                        ProgressBar& bar,
                                                        const std::atomic<bool>* cancel) const {
  pipeline::SamplingRequest request;
  request.sampling = output_sampling();
  request.chains.chains = chains;
  request.chains.threads = threads;
  request.chains.seed = seed;
  record.domain_file = domain_file;
  record.intensity_file = intensity;
  request.chains.record = std::move(record);
  request.chains.cancel = cancel;
  request.chains.progress = [&bar](long long done, long long total) { bar.update(done, total); };
  request.budget = budget.budget();
  return request;
}

int SampleFlags::run(const model::ShapeProcessModel& model, const std::string& output,
                     synthesis::SynthesisRecord record, std::ostream& out,
                     const geometry::Scene* start_tile) const {
  check(output, model.dimension);
  std::optional<core::CancellableSection> interrupt;  // Ctrl-C stops the chains; nothing is written
  ProgressBar bar("sampling", verbosity.show_progress());
  pipeline::SamplingRequest request =
      sampling_request(std::move(record), bar, core::CancellableSection::flag());
  request.ready = [&](const synthesis::Synthesizer&, const pipeline::SynthesisRun& so_far) {
    print_ready(so_far, out);
    interrupt.emplace();
  };
  const pipeline::SynthesisRun run =
      pipeline::sample_model(model, domain(model.dimension), request, start_tile);
  bar.finish();
  return write(run, output, out);
}

fit::OutputSampling SampleFlags::output_sampling() const {
  fit::OutputSampling sampling;
  sampling.iterations = iterations;
  sampling.shift_probability = shift_probability;
  sampling.shift_radius = shift_radius;
  sampling.trace_every = sampler_options().trace_every;
  sampling.decompose = decompose == "on"    ? fit::Decomposition::on
                       : decompose == "off" ? fit::Decomposition::off
                                            : fit::Decomposition::automatic;
  sampling.threads = threads;
  return sampling;
}

sample::SamplerOptions SampleFlags::sampler_options() const {
  sample::SamplerOptions options;
  options.iterations = iterations;
  options.shift_probability = shift_probability;
  options.shift_radius = shift_radius;
  if (!trace.empty())
    options.trace_every = iterations > 0 ? std::max<long long>(1, iterations / 1000) : 100;
  return options;
}

int SampleFlags::write(const pipeline::SynthesisRun& run, const std::string& output,
                       std::ostream& out) const {
  const std::vector<synthesis::SynthesisResult>& results = run.results;
  for (int c = 0; c < chains; ++c) {
    const synthesis::SynthesisResult& result = results[static_cast<std::size_t>(c)];
    const bool sampler = result.record.method == "shape-process";
    const std::string file = suffixed(output, c, chains);
    if (io::extension_of(file) == "png") {
      render::RenderOptions picture;
      picture.scale = png_scale;
      picture.text = png_text(result.record);
      render::write_png(result.scene, file, picture);
    } else {
      io::write_scene(result.scene, file, io::synthesis_provenance(result.record));
    }
    if (!trace.empty()) write_trace(suffixed(trace, c, chains), result);
    if (!png.empty()) {
      render::RenderOptions picture;
      picture.scale = png_scale;
      picture.text = png_text(result.record);
      render::write_png(result.scene, suffixed(png, c, chains), picture);
    }
    out << (sampler ? "sampled " : "synthesised ") << result.scene.elements.size()
        << " elements in " << result.record.steps << (sampler ? " steps (" : " iterations (")
        << result.record.seconds << " s";
    for (std::size_t k = 0; k < result.counters.size(); ++k)
      out << (k ? ", " : "; ") << result.counters[k].first << ' ' << result.counters[k].second;
    out << "), seed " << result.record.chain_seed << '\n';
    if (!result.record.stationary) {
      out << (sampler ? "warning: the element count was still changing after "
                      : "warning: the energy was still falling after ")
          << result.record.steps << (sampler ? " steps" : " iterations")
          << "; the output may not be at equilibrium (give --iterations)\n";
    }
    const synthesis::OutputCheck check =
        synthesis::check_output(result, run.exemplar_density, run.automatic_stop);
    if (check.short_of_density) {
      out << "warning: the chain reached " << result.scene.elements.size() << " elements where "
          << "the exemplar's density gives " << core::format_general(check.wanted, 4) << " (x"
          << core::format_fixed(check.ratio(), 2)
          << "): the model does not reach its exemplar's packing from empty\n";
    }
    out << "wrote " << file;
    if (!png.empty()) out << " and " << suffixed(png, c, chains);
    out << '\n';
  }
  return 0;
}

std::vector<std::pair<std::string, std::string>> flatten_options(const std::string& prefix,
                                                                 const nlohmann::json& object) {
  std::vector<std::pair<std::string, std::string>> out;
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object()) {
      for (auto& pair : flatten_options(key, *it)) out.push_back(std::move(pair));
    } else {
      out.emplace_back(key, it->is_string() ? it->get<std::string>() : it->dump());
    }
  }
  return out;
}

void add_sample_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  struct SampleArguments {
    std::string model, output;
    SampleFlags sample;
    DistributedFlags distributed;
  };
  auto args = std::make_shared<SampleArguments>();
  CLI::App* command = app.add_subcommand(
      "sample", "Synthesise an arrangement from a model (birth-death Metropolis-Hastings)");
  command->add_option("MODEL", args->model, "model file (.json)")->required();
  command->add_option("-o,--output", args->output, "output (.svg, .obj, .ply, .csv)")->required();
  args->sample.add_to(*command);
  args->distributed.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) {
      args->distributed.check(args->sample, args->output);
      args->sample.check(args->output);
      const model::ShapeProcessModel model = io::read_model(args->model);
      synthesis::SynthesisRecord record;
      record.command = "sample";
      record.arguments = arguments;
      record.inputs = {{"model", args->model}};
      if (args->distributed.distributed) {
        args->sample.check(args->output, model.dimension);
        return run_distributed(args->sample, args->distributed, model, args->output,
                               std::move(record), out);
      }
      return args->sample.run(model, args->output, std::move(record), out);
    };
  });
}

}  // namespace shapeproc::cli
