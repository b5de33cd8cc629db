// shapeproc sample model.json -o out.svg --size W,H[,D]: birth-death Metropolis-Hastings, and
// shapeproc synthesize EXEMPLAR -o out.svg --size ...: fit, then sample.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/render/raster.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/flags.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

namespace {

// out.svg → out-2.svg for chain 2 of several; unchanged for a single chain.
std::string suffixed(const std::string& path, int chain, int chains) {
  if (chains <= 1 || path.empty()) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + std::to_string(chain + 1) + p.extension().string())).string();
}

// The mask of an SVG domain: its filled shapes, rasterised over their own window, 2048 pixels
// along the longer side.
geometry::Raster domain_mask(const std::string& path) {
  const std::string extension = io::extension_of(path);
  if (extension == "png") return io::read_grayscale_png(path);
  if (extension != "svg") throw core::UsageError("--domain: expected an .svg (filled shapes) or a .png mask, got '" + path + "'");
  const geometry::Scene shapes = io::read_scene(path, {});
  if (shapes.dimension != 2 || shapes.elements.empty()) throw core::InputError(path, 0, "the domain has no filled shape");
  const geometry::Vec3 size = shapes.window.sizes();
  const double longest = std::max(size.x(), size.y());
  const int width = std::max(8, static_cast<int>(std::lround(2048 * size.x() / longest)));
  const int height = std::max(8, static_cast<int>(std::lround(2048 * size.y() / longest)));
  geometry::Raster mask = render::rasterize_filled(shapes, shapes.window, width, height);
  if (std::none_of(mask.values.begin(), mask.values.end(), [](float v) { return v >= 0.5f; })) {
    throw core::InputError(path, 0, "the domain has no filled shape (nothing to sample in)");
  }
  return mask;
}

}  // namespace

void SampleFlags::add_to(CLI::App& command) {
  command.add_option("--size", size, "domain W,H (2D) or W,H,D (3D), in the model's units")->required();
  command.add_option("--domain", domain, "2D domain shape: an SVG (its filled shapes) or a grayscale PNG mask (white = inside), stretched over --size");
  command.add_option("--intensity", intensity, "2D intensity map: grayscale PNG stretched over --size, scales beta (white = 1)");
  command.add_option("--iterations", iterations, "steps per chain (default: until the element count is stationary, see docs/sample.md)")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--shift-probability", shift_probability, "share of steps that shift an element (0: birth-death only)")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  command.add_option("--shift-radius", shift_radius, "largest shift (default: half the interaction range)")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--seed", seed, "random seed")->capture_default_str();
  command.add_option("--chains", chains, "independent chains; outputs get -1, -2, ... suffixes")->check(CLI::Range(1, 1000));
  command.add_option("--threads", threads, "threads for the chains (default: one per core)")->check(CLI::Range(0, 256));
  command.add_option("--boundary", boundary, "torus (periodic; default for plain rectangles and boxes) or open (default with --domain)")
      ->check(CLI::IsMember({"torus", "open"}));
  command.add_option("--trace", trace, "write element count and log density every 1/1000 of the steps (.csv)");
  command.add_option("--png", png, "also render the output to this PNG");
}

int SampleFlags::run(const model::ShapeProcessModel& model, const std::string& output, const std::string& command_name,
                     const std::vector<std::string>& arguments, nlohmann::json parameters, std::ostream& out) const {
  const auto sizes = io::parse_number_list(size);
  if (!sizes || static_cast<int>(sizes->size()) != model.dimension ||
      !std::all_of(sizes->begin(), sizes->end(), [](double v) { return v > 0 && std::isfinite(v); })) {
    throw core::UsageError("--size: expected " + std::string(model.dimension == 2 ? "W,H" : "W,H,D") +
                         " (positive) for a " + std::to_string(model.dimension) + "D model, got '" + size + "'");
  }
  if (!png.empty() && io::extension_of(png) != "png") throw core::UsageError("--png: expected a .png file, got '" + png + "'");
  if (model.dimension != 2 && (!domain.empty() || !intensity.empty())) {
    throw core::UsageError("--domain and --intensity are for 2D models");
  }
  if (boundary == "torus" && !domain.empty()) throw core::UsageError("--boundary torus needs a rectangular domain: drop --domain or use --boundary open");
  geometry::Box3 box(geometry::Vec3::Zero(), geometry::Vec3::Zero());
  for (int axis = 0; axis < model.dimension; ++axis) box.max()[axis] = (*sizes)[static_cast<std::size_t>(axis)];
  std::optional<geometry::Raster> mask, map;
  if (!domain.empty()) mask = domain_mask(domain);
  if (!intensity.empty()) map = io::read_grayscale_png(intensity);

  sample::SamplerOptions base;
  base.iterations = iterations;
  base.periodic = boundary.empty() ? domain.empty() : boundary == "torus";
  base.mask = mask ? &*mask : nullptr;
  base.intensity = map ? &*map : nullptr;
  base.shift_probability = shift_probability;
  base.shift_radius = shift_radius;
  if (!trace.empty()) base.trace_every = iterations > 0 ? std::max<long long>(1, iterations / 1000) : 100;

  // A progress bar on a terminal, over all chains; with the automatic rule (unknown length), a
  // count of the steps done.
  const bool terminal = isatty(fileno(stderr)) != 0;
  std::atomic<long long> done{0};
  std::mutex print;
  long long last_shown = -1;
  const long long total = iterations * chains;
  auto report = [&](long long add) {
    const long long now = done += add;
    std::lock_guard<std::mutex> lock(print);
    if (total > 0) {
      const long long percent = 100 * now / total;
      if (percent == last_shown) return;
      last_shown = percent;
      const int filled = static_cast<int>(percent / 4);
      std::fprintf(stderr, "\rsampling [%s%s] %3lld%%", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                   std::string(static_cast<std::size_t>(25 - filled), ' ').c_str(), percent);
      if (now >= total) std::fprintf(stderr, "\n");
    } else {
      std::fprintf(stderr, "\rsampling: %lld steps (until the element count is stationary)", now);
    }
    std::fflush(stderr);
  };

  std::vector<sample::SampleResult> results(static_cast<std::size_t>(chains));
  std::vector<double> seconds(static_cast<std::size_t>(chains));
  std::vector<std::string> errors(static_cast<std::size_t>(chains));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int c = next++; c < chains; c = next++) {
      sample::SamplerOptions options = base;
      options.seed = sample::chain_seed(seed, c);
      long long reported = 0;
      if (terminal) {
        options.progress = [&](long long step, long long) {
          report(step - reported);
          reported = step;
        };
      }
      const auto start = std::chrono::steady_clock::now();
      try {
        results[static_cast<std::size_t>(c)] = sample::sample_shape_process(model, box, options);
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(c)] = e.what();
      }
      seconds[static_cast<std::size_t>(c)] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  };
  const int thread_count = std::max(1, std::min(chains, threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))));
  std::vector<std::thread> pool;
  for (int t = 1; t < thread_count; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (terminal && total == 0) std::fprintf(stderr, "\n");
  for (const std::string& e : errors)
    if (!e.empty()) throw core::UsageError(e);

  parameters["size"] = *sizes;
  parameters["seed"] = seed;
  parameters["iterations"] = iterations > 0 ? nlohmann::json(iterations) : nlohmann::json("stationary");
  parameters["shift_probability"] = shift_probability;
  if (shift_radius > 0) parameters["shift_radius"] = shift_radius;
  parameters["boundary"] = base.periodic ? "torus" : "open";
  parameters["chains"] = chains;
  if (!domain.empty()) parameters["domain"] = domain;
  if (!intensity.empty()) parameters["intensity"] = intensity;
  for (int c = 0; c < chains; ++c) {
    const sample::SampleResult& result = results[static_cast<std::size_t>(c)];
    nlohmann::json chain_parameters = parameters;
    chain_parameters["chain"] = c + 1;
    chain_parameters["chain_seed"] = sample::chain_seed(seed, c);
    chain_parameters["steps"] = result.iterations;
    const std::string file = suffixed(output, c, chains);
    io::write_scene(result.scene, file, make_provenance(command_name, arguments, chain_parameters));
    if (!trace.empty()) {
      core::write_file_atomically(suffixed(trace, c, chains), [&](std::ostream& f) {
        f << "# shapeproc " << command_name << " seed " << seed << " chain " << c + 1 << "\nstep,elements,log_density\n";
        for (const auto& t : result.trace) f << t.step << ',' << t.elements << ',' << io::format_number(t.log_density) << '\n';
      });
    }
    if (!png.empty()) render::write_png(result.scene, suffixed(png, c, chains));
    out << "sampled " << result.scene.elements.size() << " elements in " << result.iterations << " steps ("
        << seconds[static_cast<std::size_t>(c)] << " s; births accepted " << result.births_accepted << "/"
        << result.births_proposed << ", deaths " << result.deaths_accepted << "/" << result.deaths_proposed << ", shifts "
        << result.shifts_accepted << "/" << result.shifts_proposed << "), seed " << sample::chain_seed(seed, c) << '\n';
    if (!result.stationary) {
      out << "warning: the element count was still changing after " << result.iterations
          << " steps; the output may not be at equilibrium (give --iterations)\n";
    }
    out << "wrote " << file;
    if (!png.empty()) out << " and " << suffixed(png, c, chains);
    out << '\n';
  }
  return 0;
}

void add_sample_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  struct SampleArguments {
    std::string model, output;
    SampleFlags sample;
  };
  auto args = std::make_shared<SampleArguments>();
  CLI::App* command = app.add_subcommand("sample", "Synthesise an arrangement from a model (birth-death Metropolis-Hastings)");
  command->add_option("MODEL", args->model, "model file (.json)")->required();
  command->add_option("-o,--output", args->output, "output (.svg, .obj, .ply, .csv)")->required();
  args->sample.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) {
      const model::ShapeProcessModel model = io::read_model(args->model);
      return args->sample.run(model, args->output, "sample", arguments, {{"model", args->model}}, out);
    };
  });
}

void add_synthesize_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  struct SynthesizeArguments {
    std::string input, output, model;
    FitFlags fit;
    ReaderFlags reader;
    SampleFlags sample;
  };
  auto args = std::make_shared<SynthesizeArguments>();
  CLI::App* command = app.add_subcommand("synthesize", "Fit a model to an exemplar, then sample an output from it");
  command->add_option("EXEMPLAR", args->input, "input file")->required();
  command->add_option("-o,--output", args->output, "output (.svg, .obj, .ply, .csv)")->required();
  command->add_option("--model", args->model, "also write the fitted model (.json)");
  args->fit.add_to(*command);
  args->reader.add_to(*command);
  args->sample.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) {
      if (!args->model.empty() && io::extension_of(args->model) != "json") throw core::UsageError(args->model + ": the model is written as .json");
      const fit::FitResult fitted = fit_exemplar(args->input, args->fit, args->reader, arguments);
      if (!args->model.empty()) io::write_model(fitted.model, args->model);
      print_model_summary(fitted.model, out);
      out << '\n';
      return args->sample.run(fitted.model, args->output, "synthesize", arguments,
                              {{"exemplar", args->input}, {"fit", args->fit.to_json()}, {"reader", args->reader.to_json()}}, out);
    };
  });
}

}  // namespace shapeproc::cli
