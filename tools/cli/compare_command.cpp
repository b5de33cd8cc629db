// shapeproc compare EXEMPLAR --size W,H -o DIR [--methods ...] [--seed S]: every synthesis method
// on one exemplar, each output written to DIR, and one page, DIR/index.html, with the exemplar and
// the outputs at one scale, each output's verdicts, the time each method took and the metrics
// (the shape-process paper's Fig. 5 on the user's own drawing). Each method runs exactly as
// `synthesize --method M` would, with the same seed; centroid and hausdorff are the shape process
// with those distances (the paper's Fig. 11); hybrid-M is `synthesize --method hybrid
// --start-from M`.
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/pipeline/method_comparison.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/report_command.hpp"
#include "tools/cli/stats_command.hpp"

namespace shapeproc::cli {

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
      pipeline::MethodComparisonRequest request;
      request.methods = pipeline::parse_compared_methods(args->methods);
      request.exemplar = args->exemplar;
      request.reader = args->reader.options();
      request.size = args->size;
      request.seed = args->seed;
      request.directory = args->directory;
      request.metrics = args->metrics.options();
      request.command = command_line(arguments);
      // No cancellable section: Ctrl-C ends the comparison at once; each output is written whole
      // or not at all.
      request.starting = [&out](std::size_t index, std::size_t count, const std::string& method) {
        out << '[' << index << '/' << count << "] " << method << std::endl;
      };
      request.finished = [&out](const pipeline::MethodRun& run) {
        for (const std::string& line : run.lines)
          out << "  " << core::name_options(line, flag_for) << '\n';
        if (!run.failure.empty())
          out << "  failed: " << one_line(core::name_options(run.failure, flag_for)) << '\n';
      };
      const pipeline::MethodComparison done = pipeline::compare_methods(request);
      print_report(done.report, out);
      for (const pipeline::MethodRun& run : done.runs)
        if (!run.failure.empty())
          out << "not on the page: " << run.method << " ("
              << one_line(core::name_options(run.failure, flag_for)) << ")\n";
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
