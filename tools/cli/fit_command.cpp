// shapeproc fit EXEMPLAR -o model.json: the thresholds, the maximum pseudo-likelihood and, by
// default, the maximum likelihood (fit::fit_exemplar).
#include <iomanip>
#include <limits>
#include <memory>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/fit/fit_estimate.hpp"
#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/flags.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

namespace {

struct FitArguments {
  std::string input, output;
  FitFlags fit;
  ReaderFlags reader;
  VerbosityFlags verbosity;
  BudgetFlags budget;
};

std::vector<double> number_list(const std::string& text, const char* option) {
  const auto values = io::parse_number_list(text);
  if (!values || values->empty())
    throw core::UsageError(std::string(option) + ": expected numbers separated by commas, got '" +
                           text + "'");
  return *values;
}

int run_fit(const FitArguments& args, const std::vector<std::string>& arguments,
            std::ostream& out) {
  const core::Stopwatch watch;
  if (io::extension_of(args.output) != "json")
    throw core::UsageError(args.output + ": the model is written as .json");
  core::check_writable(args.output);
  const fit::FitResult result = fit_exemplar(args.input, args.fit, args.reader, arguments,
                                             args.verbosity, args.budget.budget());
  io::write_model(result.model, args.output);

  print_model_summary(result.model, out);
  const double total = watch.seconds();
  out << std::fixed << std::setprecision(1) << "time: proxies " << result.seconds.proxies * 1e3
      << " ms, measurements " << result.seconds.measurements * 1e3 << " ms, quadrature "
      << result.seconds.quadrature * 1e3 << " ms, fit " << result.seconds.optimisation * 1e3
      << " ms; total " << total * 1e3 << " ms\n";
  out.unsetf(std::ios::fixed);
  out << "wrote " << args.output << '\n';
  return 0;
}

}  // namespace

FitProgress::FitProgress(const VerbosityFlags& verbosity)
    : verbosity_(verbosity),
      quadrature_("fitting: quadrature", verbosity.show_progress()),
      iterations_("fitting: maximum likelihood", verbosity.show_progress()) {}

void FitProgress::attach(fit::ExemplarFitOptions& options) {
  options.fit.progress = [this](const char* stage, long long done, long long total) {
    if (stage != last_stage_ && total == 0) {
      last_stage_ = stage;
      verbosity_.stage(std::string("fit: ") + stage);
      return;
    }
    quadrature_.update(done, total);
  };
  if (!options.likelihood) return;
  const int most = options.likelihood->max_iterations;
  options.likelihood->progress = [this, most](const fit::MleProgress& at) {
    quadrature_.finish();
    verbosity_.stage("mle: iteration " + std::to_string(at.iteration) + ", largest |z| " +
                     core::format_general(at.worst_z, 3) + ", effective sample " +
                     core::format_general(at.effective_size, 3) + " (" + std::to_string(at.chains) +
                     " chains), " + core::format_general(at.seconds, 3) + " s");
    iterations_.update(at.iteration, most);
  };
}

void FitProgress::finish() {
  quadrature_.finish();
  iterations_.finish();
}

fit::FitResult fit_exemplar(const std::string& input, const FitFlags& flags,
                            const ReaderFlags& reader, const std::vector<std::string>& arguments,
                            const VerbosityFlags& verbosity, const core::ResourceBudget& budget,
                            geometry::Scene* fitted) {
  fit::ExemplarFitOptions options = flags.exemplar_options(reader);  // checked before reading
  verbosity.stage("reading " + input);
  const geometry::Scene read = io::read_scene(input, reader.options());
  core::check_budget(fit::estimate_fit(read, options.fit).resources, budget, "the fit of " + input,
                     "{quadrature}, {directions} or the thresholds");
  FitProgress progress(verbosity);
  progress.attach(options);
  fit::ExemplarFit fit;
  try {
    fit = fit::fit_exemplar(read, options);
  } catch (const std::invalid_argument& e) {
    throw core::InputError(input, 0, e.what());
  }
  progress.finish();
  flags.record(fit.result.model, input, reader, arguments);
  if (fitted) *fitted = std::move(fit.exemplar);
  return std::move(fit.result);
}

void FitFlags::add_to(CLI::App& command) {
  command.add_option("--directions", directions,
                     "canonical directions: 2D an even number or 1 (default 8); 3D 12 or 1");
  auto* q = command.add_option("--quantiles", quantiles, "quantile orders of the thresholds")
                ->capture_default_str();
  auto* t = command.add_option("--thresholds", thresholds,
                               "thresholds d0,d1,... for every pair and axis");
  q->excludes(t);
  command
      .add_option("--edge", edge,
                  "edge treatment: none (the window as drawn, cut at its edges), periodic, border "
                  "or stationary (maximum likelihood of the window as a piece of a larger "
                  "drawing); auto: periodic for a --tile, else stationary for the maximum "
                  "likelihood of an exemplar that is not packed, else none")
      ->check(CLI::IsMember({"auto", "none", "periodic", "border", "stationary"}))
      ->capture_default_str();
  add_measurement_kind_options(command, distance, direction);
  command
      .add_option("--quadrature", quadrature,
                  "quadrature cells along the window's longest side (default 48 in 2D, 8 in 3D)")
      ->check(non_negative_number());
  command
      .add_option(
          "--shapes-per-location", shapes_per_location,
          "shapes crossed with each quadrature location, in rotation (default: every distinct "
          "shape, up to 64)")
      ->check(non_negative_number());
  command.add_flag(
      "--quadrature-lines", lines,
      "2D: integrate each row of quadrature cells exactly along the row (slower; see docs/fit.md)");
  command
      .add_option("--refine", refine,
                  "levels of adaptive refinement of quadrature cells near boundaries (default 0)")
      ->check(CLI::Range(0, 6));
  command
      .add_option("--proxy-tolerance", proxy_tolerance,
                  "proxy simplification, fraction of each element's diagonal")
      ->capture_default_str();
  command
      .add_option(
          "--data-weight", data_weight,
          "share of the window's measure the data points carry in the quadrature (see docs/fit.md)")
      ->capture_default_str();
  command
      .add_option("--near-births", near_births,
                  "share of birth proposals placed where the exemplar had a neighbour, in the "
                  "fit's chains and every chain of the model (0: all uniform; auto: 0.5 where the "
                  "chains grow a lattice as a crystal, else 0; see docs/mathematics.md)")
      ->capture_default_str();
  command
      .add_option("--estimator", estimator,
                  "mle (maximum likelihood by MCMC, started from the MPL fit; every edge "
                  "treatment), mpl (maximum pseudo-likelihood alone, fast) or auto (mle for a "
                  "--tile and up to 60 elements, else mpl); every fit is then checked on the "
                  "output's scale; "
                  "see docs/fit.md")
      ->check(CLI::IsMember({"auto", "mpl", "mle"}))
      ->capture_default_str();
  command.add_option("--mle-chains", mle_chains, "MLE: chains per iteration")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  command.add_option("--mle-steps", mle_steps, "MLE: steps of each chain after its burn-in")
      ->check(positive_number())
      ->capture_default_str();
  command.add_option("--mle-seed", mle_seed, "MLE: random seed of its chains")
      ->capture_default_str();
}

void FitFlags::add_threads_to(CLI::App& command) {
  command
      .add_option("--threads", threads,
                  "threads of the quadrature and of the maximum likelihood's chains (default: one "
                  "per core; the model does not depend on them)")
      ->check(CLI::Range(0, 256));
}

fit::MleOptions FitFlags::mle_options() const {
  fit::MleOptions o;
  o.sampling.threads = threads;
  o.sampling.chains = mle_chains;
  o.sampling.steps = mle_steps;
  o.sampling.seed = mle_seed;
  o.window = edge == "stationary" ? fit::WindowModel::stationary
             : edge == "auto"     ? fit::WindowModel::automatic
                                  : fit::WindowModel::own;
  return o;
}

std::string FitFlags::edge_for(const ReaderFlags& reader) const {
  if (edge != "auto") return edge;
  return reader.tile ? "periodic" : "none";
}

fit::ExemplarFitOptions FitFlags::exemplar_options(const ReaderFlags& reader) const {
  fit::ExemplarFitOptions options;
  options.fit = this->options(reader);
  options.tile = reader.tile;
  if (estimator == "mpl")
    options.likelihood.reset();
  else
    options.likelihood = mle_options();
  if (estimator == "mle") options.likelihood_elements = std::numeric_limits<std::size_t>::max();
  return options;
}

void FitFlags::record(model::ShapeProcessModel& model, const std::string& input,
                      const ReaderFlags& reader, const std::vector<std::string>& arguments) const {
  model::FitRecord& record = *model.fit;
  record.exemplar = input;
  record.arguments = arguments;
  record.options = flatten_options("reader", reader.to_json());
  nlohmann::json flag_values = to_json();
  flag_values["edge"] = edge_for(reader);
  flag_values["directions"] = model.measurement.directions;
  for (auto& option : flatten_options("fit", flag_values))
    record.options.push_back(std::move(option));
}

fit::FitOptions FitFlags::options(const ReaderFlags& reader) const {
  fit::FitOptions o;
  o.threads = threads;
  const std::string treatment = edge_for(reader);
  if (treatment == "stationary" && estimator == "mpl")
    throw core::UsageError("--edge stationary is a maximum-likelihood fit: use --estimator mle");
  o.measurement.directions = directions;
  o.quantiles = number_list(quantiles, "--quantiles");
  if (!thresholds.empty()) o.thresholds = number_list(thresholds, "--thresholds");
  o.boundary = treatment == "periodic" ? geometry::Boundary::torus : geometry::Boundary::open;
  o.edge = treatment == "border" ? geometry::EdgeTreatment::border : geometry::EdgeTreatment::none;
  o.measurement.distance = distance_kind(distance);
  o.measurement.direction = direction_kind(direction);
  o.quadrature = quadrature;
  o.shapes_per_location = shapes_per_location;
  o.refinement = refine;
  o.lines = lines;
  if (!(proxy_tolerance >= 0 && proxy_tolerance < 1))
    throw core::UsageError("--proxy-tolerance must be in [0, 1)");
  o.measurement.proxy_tolerance = proxy_tolerance;
  if (!(data_weight >= 0 && data_weight < 1))
    throw core::UsageError("--data-weight must be in [0, 1)");
  o.data_weight = data_weight;
  if (near_births != "auto") {
    const std::optional<double> share = io::parse_number(near_births);
    if (!share || !(*share >= 0 && *share <= 0.95))
      throw core::UsageError("--near-births must be a share in [0, 0.95] or auto, got '" +
                             near_births + "'");
    o.near_birth_share = *share;
  }
  return o;
}

nlohmann::json FitFlags::to_json() const {
  return {{"directions", directions},
          {"quantiles", quantiles},
          {"thresholds", thresholds},
          {"edge", edge},
          {"estimator", estimator},
          {"distance", distance},
          {"direction", direction},
          {"quadrature", quadrature},
          {"shapes_per_location", shapes_per_location},
          {"refine", refine},
          {"lines", lines},
          {"proxy_tolerance", proxy_tolerance},
          {"data_weight", data_weight},
          {"near_births", near_births}};
}

void add_fit_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  auto args = std::make_shared<FitArguments>();
  CLI::App* command = app.add_subcommand(
      "fit", "Fit the shape-process model to an exemplar (maximum likelihood by MCMC)");
  command->add_option("EXEMPLAR", args->input, "input file")->required();
  command->add_option("-o,--output", args->output, "model file (.json)")->required();
  args->fit.add_to(*command);
  args->fit.add_threads_to(*command);
  args->reader.add_to(*command);
  args->verbosity.add_to(*command);
  args->budget.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) { return run_fit(*args, arguments, out); };
  });
}

}  // namespace shapeproc::cli
