// shapeproc report EXEMPLAR OUTPUT... -o DIR [--model model.json]: index.html, pictures and
// metrics.json comparing outputs with their exemplar (report::write_comparison_report).
#include "tools/cli/report_command.hpp"

#include <memory>

#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/stats_command.hpp"

namespace shapeproc::cli {

void print_report(const report::ComparisonReport& report, std::ostream& out) {
  // The verdicts first: what a person would notice, one line per output.
  for (const report::OutputSummary& o : report.outputs)
    out << o.label << ": " << o.verdicts << '\n';
  out << "wrote " << report.index << " (" << report.outputs.size() + 1
      << " pictures, metrics.json, verdicts.md)\n";
  for (const report::OutputSummary& o : report.outputs) {
    out << "  " << o.file << ": " << o.elements << " elements, " << o.colliding_pairs
        << " colliding pairs, W1 nearest " << o.w1_nearest << ", W1 pairs " << o.w1_pairs
        << ", neighbourhood distance " << o.neighbourhood << " a²\n";
  }
  for (const std::string& file : report.empty_outputs)
    out << "not on the page: " << file << " (it holds no element: its chain ended empty)\n";
}

void add_report_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  struct ReportArguments {
    report::ComparisonRequest request;
    MetricFlags metrics;
    ReaderFlags reader;
  };
  auto args = std::make_shared<ReportArguments>();
  CLI::App* command = app.add_subcommand("report",
                                         "Write DIR/index.html (self-contained) with pictures, "
                                         "verdicts, distance charts and metrics comparing outputs "
                                         "with their exemplar, and DIR/metrics.json");
  command->add_option("EXEMPLAR", args->request.exemplar, "the exemplar")->required();
  command->add_option("OUTPUTS", args->request.outputs, "outputs to compare with it")->required();
  command->add_option("-o,--output", args->request.directory, "report directory")->required();
  command->add_option("--model", args->request.model,
                      "the fitted model: its interaction function is drawn, its axes used");
  args->metrics.add_to(*command);
  args->reader.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) {
      report::ComparisonRequest request = args->request;
      request.metrics = args->metrics.options();
      request.reader = args->reader.options();
      request.command = command_line(arguments);
      print_report(report::write_comparison_report(request), out);
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
