// shapeproc compare EXEMPLAR --size W,H -o DIR [--methods ...] [--seed S]: every synthesis method
// on one exemplar, each output written to DIR, and one page, DIR/index.html, with the exemplar and
// the outputs at one scale, each output's verdicts, the time each method took and the metrics
// (the shape-process paper's Fig. 5 on the user's own drawing). Each method runs exactly as
// `synthesize --method M` would, with the same seed; centroid and hausdorff are the shape process
// with those distances (the paper's Fig. 11); hybrid-M is `synthesize --method hybrid
// --start-from M`.
#include <filesystem>
#include <memory>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/io/domain_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/report_command.hpp"
#include "tools/cli/stats_command.hpp"
#include "tools/cli/synthesize_command.hpp"

namespace shapeproc::cli {

namespace {

const std::vector<std::string> kMethods = {
    "tile",     "shape-process", "ma-em",        "ijiri",          "davison",
    "centroid", "hausdorff",     "hybrid-ma-em", "hybrid-davison", "hybrid-ijiri"};

std::vector<std::string> parse_methods(const std::string& list) {
  std::vector<std::string> out;
  if (list.empty()) throw core::UsageError("--methods: no method given");
  for (const std::string& name : io::split(list, ',')) {
    if (std::find(kMethods.begin(), kMethods.end(), name) == kMethods.end())
      throw core::UsageError("--methods: unknown method '" + name +
                             "' (expected tile, shape-process, ma-em, ijiri, davison, centroid, "
                             "hausdorff, hybrid-ma-em, hybrid-davison or hybrid-ijiri)");
    if (std::find(out.begin(), out.end(), name) != out.end())
      throw core::UsageError("--methods: '" + name + "' is given twice");
    out.push_back(name);
  }
  return out;
}

// The `synthesize` arguments that run `method` (a name of --methods).
SynthesizeArguments synthesize_request(const std::string& method, const std::string& exemplar,
                                       const ReaderFlags& reader, const std::string& size,
                                       std::uint64_t seed, const std::string& output,
                                       const std::string& model) {
  SynthesizeArguments args;
  args.input = exemplar;
  args.output = output;
  args.model = model;
  args.reader = reader;
  args.sample.size = size;
  args.sample.seed = seed;
  args.sample.exemplar_multiples = true;
  if (method == "centroid" || method == "hausdorff") {
    args.fit.distance = method;
  } else if (method.rfind("hybrid-", 0) == 0) {
    args.method = "hybrid";
    args.start_from = method.substr(7);
  } else if (method != "shape-process") {
    args.method = method;
  }
  return args;
}

// The `synthesize` command line that `args` stand for: what the outputs' records name as their
// source.
std::vector<std::string> command_line_of(const SynthesizeArguments& args) {
  std::vector<std::string> a = {"shapeproc", "synthesize", args.input};
  const std::vector<std::string> flags = args.reader.arguments();
  a.insert(a.end(), flags.begin(), flags.end());
  a.insert(a.end(), {"--size", args.sample.size, "--seed", std::to_string(args.sample.seed), "-o",
                     args.output});
  if (args.fit.distance != FitFlags{}.distance)
    a.insert(a.end(), {"--distance", args.fit.distance});
  if (args.method != "shape-process") a.insert(a.end(), {"--method", args.method});
  if (args.method == "hybrid") a.insert(a.end(), {"--start-from", args.start_from});
  if (!args.model.empty()) a.insert(a.end(), {"--model", args.model});
  return a;
}

// Runs one method as `synthesize` would; returns the reason it failed, empty when it did not.
// Ctrl-C stops the whole comparison.
std::string run_one_method(SynthesizeArguments args, const std::vector<std::string>& arguments,
                           std::ostream& out) {
  try {
    run_synthesize(args, arguments, out);
    return {};
  } catch (const core::Cancelled&) {
    throw;
  } catch (const core::InputError& e) {
    return one_line(e.shown(flag_for));
  } catch (const core::UsageError& e) {
    return one_line(e.shown(flag_for));
  } catch (const core::ArgumentError& e) {
    return one_line(e.what());
  } catch (const std::exception& e) {
    return "internal error: " + one_line(e.what());
  }
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  struct CompareArguments {
    std::string exemplar, directory, size, methods = "tile,shape-process,ma-em,ijiri,davison";
    std::uint64_t seed = 1;
    ReaderFlags reader;
    MetricFlags metrics;
  };
  auto args = std::make_shared<CompareArguments>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Run every synthesis method on one exemplar and write DIR/index.html: the outputs side by "
      "side, each with its verdicts, times and metrics");
  command->add_option("EXEMPLAR", args->exemplar, "the exemplar")->required();
  command->add_option("-o,--output", args->directory, "report directory")->required();
  command
      ->add_option("--size", args->size,
                   "output domain W,H (2D) or W,H,D (3D), in the exemplar's units or as multiples "
                   "of its window: 3W,3H")
      ->required();
  command->add_option("--seed", args->seed, "seed of every method")->capture_default_str();
  command
      ->add_option(
          "--methods", args->methods,
          "comma-separated: tile (the exemplar repeated: the baseline), shape-process, ma-em, "
          "ijiri, davison, centroid, hausdorff, "
          "hybrid-ma-em, hybrid-davison, hybrid-ijiri (centroid and hausdorff: the shape "
          "process with that distance; hausdorff costs about 7.6 ms per sampler step and "
          "is left out of the defaults; hybrid-M: M's output, then the shape-process "
          "sampler)")
      ->capture_default_str();
  args->reader.add_to(*command);
  args->metrics.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) {
      const std::vector<std::string> methods = parse_methods(args->methods);
      // The exemplar read once before anything runs: a bad file is one error, not one per method.
      const geometry::Scene exemplar = io::read_scene(args->exemplar, args->reader.options());
      const auto size = io::parse_size(args->size, &exemplar.window);
      if (!size || static_cast<int>(size->size()) != exemplar.dimension)
        throw core::UsageError(
            "--size: expected " + std::string(exemplar.dimension == 3 ? "W,H,D" : "W,H") +
            " (positive) for a " + std::to_string(exemplar.dimension) +
            "D exemplar, or multiples of its window such as 3W,3H; got '" + args->size + "'");
      const std::filesystem::path directory(args->directory);
      if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory))
        throw core::UsageError(args->directory + ": exists and is not a directory");
      std::filesystem::create_directories(directory);
      const std::string extension = io::extension_of(args->exemplar) == "svg"   ? "svg"
                                    : io::extension_of(args->exemplar) == "csv" ? "csv"
                                                                                : "obj";
      report::ComparisonRequest request;
      request.exemplar = args->exemplar;
      request.directory = args->directory;
      request.reader = args->reader.options();
      request.metrics = args->metrics.options();
      request.command = command_line(arguments);
      std::vector<std::string> failed;
      for (std::size_t i = 0; i < methods.size(); ++i) {
        const std::string& method = methods[i];
        out << '[' << i + 1 << '/' << methods.size() << "] " << method << std::endl;
        const std::string output = (directory / (method + "." + extension)).string();
        const std::string model =
            method == "shape-process" ? (directory / "model.json").string() : std::string();
        std::ostringstream said;
        const core::Stopwatch watch;
        const SynthesizeArguments one = synthesize_request(method, args->exemplar, args->reader,
                                                           args->size, args->seed, output, model);
        const std::string reason = run_one_method(one, command_line_of(one), said);
        const double seconds = watch.seconds();
        std::istringstream lines(said.str());
        for (std::string line; std::getline(lines, line);) out << "  " << line << '\n';
        if (!reason.empty()) {
          out << "  failed: " << reason << '\n';
          failed.push_back(method + " (" + reason + ")");
          continue;
        }
        request.outputs.push_back(output);
        request.labels.push_back(method);
        request.timings.emplace_back(method, seconds);
        if (!model.empty()) request.model = model;
      }
      if (request.outputs.empty())
        throw core::UsageError("no method could synthesise from " + args->exemplar + ": " +
                               failed.front());
      print_report(report::write_comparison_report(request), out);
      for (const std::string& f : failed) out << "not on the page: " << f << '\n';
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
