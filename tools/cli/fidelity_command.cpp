// shapeproc fidelity EXEMPLAR: fits the exemplar (or takes --model) and checks that the model
// reproduces it (evaluation/fidelity.hpp): its statistics on the exemplar's own window over many
// chains, and the density, collisions and shape mix of a larger output. --row prints one line of
// the table scripts/fidelity.sh makes.
#include <cmath>
#include <iomanip>
#include <memory>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/evaluation/fidelity.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/flags.hpp"

namespace shapeproc::cli {

namespace {

struct FidelityArguments {
  std::string input, model;
  FitFlags fit;
  ReaderFlags reader;
  VerbosityFlags verbosity;
  BudgetFlags budget;
  evaluation::FidelityOptions options;
  bool row = false;
};

std::string g(double v, int digits = 3) { return core::format_general(v, digits); }

void print_row(const std::string& name, const evaluation::FidelityReport& r,
               const model::ShapeProcessModel& model, std::ostream& out) {
  out << "| " << name << " | " << r.exemplar_elements << " | " << g(r.worst_count_z) << " | "
      << g(r.worst_pair_z)
      << (r.penalised > 0 ? " (" + std::to_string(r.penalised) + " prior-shifted)" : "") << " | "
      << g(r.density_ratio) << (r.outputs > 1 ? " ± " + g(r.density_ratio_error, 2) : std::string())
      << " | " << r.exemplar_collisions << " / " << r.output_collisions << " | "
      << (std::isnan(r.class_p_value)
              ? std::string("-")
              : g(r.class_p_value) + " (" + std::to_string(model.shape_classes.size()) + ")")
      << " |\n";
}

void print_report(const evaluation::FidelityReport& r, const evaluation::FidelityOptions& o,
                  std::ostream& out) {
  out << "own window, " << o.sampling.chains
      << " chains: statistic, exemplar, mean ± se, z (against the fit's target where its "
         "attraction prior lowers it)\n";
  for (const evaluation::StatisticCheck& c : r.own_window) {
    out << "  " << std::left << std::setw(34) << c.name << std::right << std::setw(8)
        << g(c.exemplar, 4) << std::setw(20) << (g(c.mean, 4) + " ± " + g(c.standard_error, 2))
        << std::setw(8) << g(c.z, 2)
        << (c.target != c.exemplar ? "  (attraction prior: target " + g(c.target, 4) + ")"
                                   : std::string())
        << (std::abs(c.z) > 3 ? "  (beyond 3 se)" : "") << '\n';
  }
  out << "largest |z|: counts " << g(r.worst_count_z) << ", pairs " << g(r.worst_pair_z) << '\n';
  out << r.outputs << " output(s) " << g(o.scale)
      << " x each side (torus): " << g(r.output_elements, 4) << " elements on average, density x"
      << g(r.density_ratio) << (r.outputs > 1 ? " ± " + g(r.density_ratio_error, 2) : std::string())
      << " the exemplar's; colliding pairs " << r.output_collisions << " (exemplar "
      << r.exemplar_collisions << ")\n";
  if (!std::isnan(r.class_p_value))
    out << "shape classes: chi-square " << g(r.class_chi_square) << " on " << r.class_degrees
        << " degree(s) of freedom, p = " << g(r.class_p_value) << '\n';
  out << "novelty: patch copy share " << g(r.patch_copy_share, 2) << " (chance "
      << g(r.patch_copy_chance, 2) << "), largest copied patch " << g(r.largest_copied_patch, 2)
      << "; "
      << (r.lattice_exemplar ? "a lattice exemplar, its own repeat its only faithful arrangement"
                             : std::to_string(r.outputs_repeating) + " of " +
                                   std::to_string(r.outputs) + " output(s) repeat the exemplar")
      << '\n';
}

int run_fidelity(const FidelityArguments& args, const std::vector<std::string>& arguments,
                 std::ostream& out) {
  // The exemplar as the model was fitted: a small tile repeated as often as its fit did.
  geometry::Scene exemplar;
  model::ShapeProcessModel model;
  if (args.model.empty()) {
    model = fit_exemplar(args.input, args.fit, args.reader, arguments, args.verbosity,
                         args.budget.budget(), &exemplar)
                .model;
  } else {
    model = io::read_model(args.model);
    exemplar = read_fitting_exemplar(args.input, args.reader, model_tile_repeats(model)).scene;
  }
  const std::string edge = args.fit.edge_for(args.reader);
  const geometry::Boundary boundary =
      edge == "periodic" ? geometry::Boundary::torus : geometry::Boundary::open;
  args.verbosity.stage("checking the model against the exemplar");
  const evaluation::FidelityReport report = evaluation::check_fidelity(
      exemplar, model, boundary,
      edge == "border" ? geometry::EdgeTreatment::border : geometry::EdgeTreatment::none,
      args.options);
  if (args.row)
    print_row(std::filesystem::path(args.input).filename().string(), report, model, out);
  else
    print_report(report, args.options, out);
  return 0;
}

}  // namespace

void add_fidelity_command(CLI::App& app, Action& action,
                          const std::vector<std::string>& arguments) {
  auto args = std::make_shared<FidelityArguments>();
  CLI::App* command = app.add_subcommand(
      "fidelity",
      "Check that the fitted model reproduces its exemplar (counts, pairs, density, "
      "collisions, shape mix)");
  command->add_option("EXEMPLAR", args->input, "input file")->required();
  command->add_option("--model", args->model, "a model fitted to EXEMPLAR (default: fit it now)");
  command
      ->add_option("--chains", args->options.sampling.chains, "chains on the exemplar's own window")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  command->add_option("--seed", args->options.sampling.seed, "random seed")->capture_default_str();
  command->add_option("--scale", args->options.scale, "the output's sides, in exemplar sides")
      ->check(positive_number())
      ->capture_default_str();
  command
      ->add_option("--outputs", args->options.outputs,
                   "independent outputs whose mean density is checked")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_flag("--row", args->row,
                    "print one row of the fidelity table (scripts/fidelity.sh)");
  args->fit.add_to(*command);
  args->reader.add_to(*command);
  args->verbosity.add_to(*command);
  args->budget.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) { return run_fidelity(*args, arguments, out); };
  });
}

}  // namespace shapeproc::cli
