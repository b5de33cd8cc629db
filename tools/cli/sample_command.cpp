// shapeproc sample model.json -o out.svg --size W,H[,D]: birth-death Metropolis-Hastings.
#include <chrono>
#include <algorithm>
#include <memory>

#include "libshapeproc/io/atomic_file.hpp"
#include "libshapeproc/io/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

namespace {

struct SampleArguments {
  std::string model, output, size, boundary = "torus", trace;
  long long iterations = 0;
  std::uint64_t seed = 1;
};

int run_sample(const SampleArguments& args, const std::vector<std::string>& arguments, std::ostream& out) {
  const model::ShapeProcessModel model = io::read_model(args.model);
  const auto sizes = io::parse_number_list(args.size);
  if (!sizes || static_cast<int>(sizes->size()) != model.dimension ||
      !std::all_of(sizes->begin(), sizes->end(), [](double v) { return v > 0; })) {
    throw io::UsageError("--size: expected " + std::string(model.dimension == 2 ? "W,H" : "W,H,D") +
                         " (positive) for a " + std::to_string(model.dimension) + "D model, got '" + args.size + "'");
  }
  geometry::Box3 domain(geometry::Vec3::Zero(), geometry::Vec3::Zero());
  for (int axis = 0; axis < model.dimension; ++axis) domain.max()[axis] = (*sizes)[static_cast<std::size_t>(axis)];
  sample::SamplerOptions options;
  options.iterations = args.iterations;
  options.seed = args.seed;
  options.periodic = args.boundary == "torus";
  if (!args.trace.empty()) {
    options.trace_every = std::max<long long>(1, (args.iterations > 0 ? args.iterations : sample::default_iterations(model, domain)) / 1000);
  }
  const auto start = std::chrono::steady_clock::now();
  const sample::SampleResult result = sample::sample_shape_process(model, domain, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const nlohmann::json parameters = {{"model", args.model},    {"size", *sizes},           {"seed", args.seed},
                                     {"iterations", result.iterations}, {"boundary", args.boundary}};
  io::write_scene(result.scene, args.output, make_provenance("sample", arguments, parameters));
  if (!args.trace.empty()) {
    io::write_file_atomically(args.trace, [&](std::ostream& file) {
      file << "step,elements,log_density\n";
      for (const auto& t : result.trace) file << t.step << ',' << t.elements << ',' << io::format_number(t.log_density) << '\n';
    });
  }
  out << "sampled " << result.scene.elements.size() << " elements in " << result.iterations << " steps ("
      << seconds << " s; births accepted " << result.births_accepted << "/" << result.births_proposed << ", deaths "
      << result.deaths_accepted << "/" << result.deaths_proposed << "), seed " << args.seed << "\nwrote " << args.output << '\n';
  return 0;
}

}  // namespace

void add_sample_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  auto args = std::make_shared<SampleArguments>();
  CLI::App* command = app.add_subcommand("sample", "Synthesise an arrangement from a model (birth-death Metropolis-Hastings)");
  command->add_option("MODEL", args->model, "model file (.json)")->required();
  command->add_option("-o,--output", args->output, "output (.svg, .obj, .ply, .csv)")->required();
  command->add_option("--size", args->size, "domain W,H (2D) or W,H,D (3D), in the model's units")->required();
  command->add_option("--iterations", args->iterations, "steps (default: 200 per expected element, at least 20,000)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--seed", args->seed, "random seed")->capture_default_str();
  command->add_option("--boundary", args->boundary, "torus (periodic) or open")
      ->check(CLI::IsMember({"torus", "open"}))
      ->capture_default_str();
  command->add_option("--trace", args->trace, "write element count and log density per step block (.csv)");
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) { return run_sample(*args, arguments, out); };
  });
}

}  // namespace shapeproc::cli
