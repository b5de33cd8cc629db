// Option groups shared by subcommands: the fit's options (fit, synthesize) and the sampler's
// (sample, synthesize).
#pragma once

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/fit/mcmc_mle.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/geometry/proxy.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/pipeline/synthesis_run.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/synthesis_record.hpp"
#include "tools/cli/common.hpp"
#include "tools/cli/progress.hpp"

namespace shapeproc::cli {

struct FitFlags {
  int directions = 0;
  std::string quantiles = "0,0.1,0.2";
  std::string thresholds;
  std::string edge =
      "auto";  // none, periodic, border or stationary; auto: periodic for a --tile, else none
  std::string distance = "shape";
  std::string direction = "gravitation";
  int quadrature = 0;
  int shapes_per_location = 0;
  int refine = 0;
  bool lines = false;
  double proxy_tolerance = geometry::ProxyOptions{}.tolerance;
  double data_weight = fit::FitOptions{}.data_weight;
  std::string near_births = "auto";  // a share in [0, 0.95], or auto (fit::kAutomaticNearBirths)
  std::string estimator = "auto";
  int mle_chains = fit::MleOptions{}.sampling.chains;
  long long mle_steps = fit::MleOptions{}.sampling.steps;
  std::uint64_t mle_seed = fit::MleOptions{}.sampling.seed;
  int threads = 0;  // of the quadrature and the MLE's chains; 0: one per core

  void add_to(CLI::App& command);
  // --threads, for commands that have no other (fit; synthesize passes its sampling threads).
  void add_threads_to(CLI::App& command);
  // The edge treatment, with auto resolved for the reader's flags.
  std::string edge_for(const ReaderFlags& reader) const;
  fit::FitOptions options(const ReaderFlags& reader) const;  // throws core::UsageError
  fit::MleOptions mle_options() const;
  // The whole fit's options (the pseudo-likelihood's, the tile, the maximum likelihood's with
  // --estimator mle), without progress reports.
  fit::ExemplarFitOptions exemplar_options(const ReaderFlags& reader) const;
  // Fills the fitted model's record: the exemplar's file, the command line, the reader's and the
  // fit's options.
  void record(model::ShapeProcessModel& model, const std::string& input, const ReaderFlags& reader,
              const std::vector<std::string>& arguments) const;
  nlohmann::json to_json() const;
};

// The progress of a fit on standard error: its stages with --verbose, bars over the quadrature
// and the maximum likelihood's iterations on a terminal. Lives while the fit it is attached to
// runs.
class FitProgress {
 public:
  explicit FitProgress(const VerbosityFlags& verbosity);
  void attach(fit::ExemplarFitOptions& options);
  void finish();

 private:
  const VerbosityFlags& verbosity_;
  ProgressBar quadrature_, iterations_;
  std::string last_stage_;
};

// Reads and fits an exemplar; the model's `fit` record gets the exemplar, the arguments, the
// reader and fit options. Fit failures become core::InputError naming the exemplar. The fit is
// checked against `budget` right after reading, before any fitting. `fitted`, when given,
// receives the exemplar as fitted (a small tile repeated).
fit::FitResult fit_exemplar(const std::string& input, const FitFlags& flags,
                            const ReaderFlags& reader, const std::vector<std::string>& arguments,
                            const VerbosityFlags& verbosity, const core::ResourceBudget& budget,
                            geometry::Scene* fitted = nullptr);

struct SampleFlags {
  std::string size, domain_file, intensity, boundary, trace, png, decompose = "auto";
  long long iterations = 0;
  std::uint64_t seed = 1;
  int chains = 1, threads = 0;
  bool force = false;  // overwrite existing outputs
  double shift_probability = sample::SamplerOptions{}.shift_probability;
  double shift_radius = 0.0;
  double png_scale = 0.0;
  VerbosityFlags verbosity;
  BudgetFlags budget;
  // --size may give multiples of the exemplar's window ("3W,3H", io::parse_size): set by
  // add_to; the window is known once the exemplar is read (set_exemplar).
  bool exemplar_multiples = false;
  std::optional<geometry::Box3> exemplar_window;

  // `sampler_options`: also --intensity, --shift-probability and --shift-radius, which only the
  // shape process's sampler takes. `exemplar_multiples`: a command that reads an exemplar.
  void add_to(CLI::App& command, bool sampler_options = true, bool exemplar_multiples = false);
  // The exemplar whose window --size's multiples refer to.
  void set_exemplar(const geometry::Scene& exemplar) { exemplar_window = exemplar.window; }
  // Checks what can be checked before any expensive work: --size's syntax (and its count when
  // `dimension` is known, else 2 or 3), the output, --png and --trace extensions, --boundary with
  // --domain, and that the mask and map files exist. Throws core::UsageError or core::InputError.
  void check(const std::string& output, int dimension = 0) const;
  // The output domain (--size, --boundary, --domain, --intensity) for a `dimension`-D model.
  geometry::Domain domain(int dimension) const;
  // Every file the run writes for `output`: each chain's output (suffixed -1, -2, ... with
  // several chains) and its record beside a .csv, its picture and its trace.
  std::vector<std::string> files_written(const std::string& output) const;
  // Steps a run may take: some hours at the sampler's fraction of a microsecond per step.
  static constexpr long long kMaxIterations = 10'000'000'000;
  // The sampler's options from --iterations, --shift-probability, --shift-radius and --trace.
  sample::SamplerOptions sampler_options() const;
  // The same, with --decompose and --threads, for fit::output_sampler_options.
  fit::OutputSampling output_sampling() const;
  // Samples `model` into `output` (suffixed per chain); `record` holds the command's part of the
  // outputs' record (command, arguments, inputs, options). Prints a line per chain. Returns the
  // exit code.
  // `start_tile`, when given: every chain starts from it repeated over the domain
  // (geometry::tile_over; sample::SamplerOptions::start).
  int run(const model::ShapeProcessModel& model, const std::string& output,
          synthesis::SynthesisRecord record, std::ostream& out,
          const geometry::Scene* start_tile = nullptr) const;
  // The library's request for these flags (pipeline/synthesis_run.hpp): sampling, chains, seed,
  // budget; `record` holds the command's part of the outputs' record; the chains report to `bar`
  // and stop when `cancel` is set.
  pipeline::SamplingRequest sampling_request(synthesis::SynthesisRecord record, ProgressBar& bar,
                                             const std::atomic<bool>* cancel) const;
  // Writes each chain's output (suffixed per chain), its picture and its trace, with a line per
  // chain and the warnings its count and stopping rule call for. Returns the exit code.
  int write(const pipeline::SynthesisRun& run, const std::string& output, std::ostream& out) const;
};

// What a run says once its method is ready, before its chains run: what the method learnt, and
// its warnings, with the library's {option} marks named as flags.
void print_ready(const pipeline::SynthesisRun& so_far, std::ostream& out);

// A JSON object's leaves as (prefix.key, text) pairs, in key order (for a record's options).
std::vector<std::pair<std::string, std::string>> flatten_options(const std::string& prefix,
                                                                 const nlohmann::json& object);

}  // namespace shapeproc::cli
