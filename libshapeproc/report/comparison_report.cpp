#include "libshapeproc/report/comparison_report.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/evaluation/envelope.hpp"
#include "libshapeproc/evaluation/verdicts.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/report/html_report.hpp"
#include "libshapeproc/report/metrics_json.hpp"
#include "libshapeproc/report/verdict_markdown.hpp"

namespace shapeproc::report {

namespace {

// The goodness-of-fit table a maximum-likelihood fit stored in the model (nothing for others, or
// for a table the file does not hold whole: hand-edited, or of another version).
void read_goodness(const model::ShapeProcessModel& model, Report& r) {
  if (!model.fit || !model.fit->likelihood) return;
  const model::LikelihoodRecord& e = *model.fit->likelihood;
  const std::vector<std::string> names = model::statistic_names(model);
  const std::size_t n = names.size();
  if (e.observed.size() != n || e.expected.size() != n || e.z.size() != n) return;
  const bool errors = e.expected_standard_error.size() == n;
  for (std::size_t i = 0; i < n; ++i) {
    GoodnessRow row;
    row.statistic = names[i];
    row.exemplar = e.observed[i];
    row.model = e.expected[i];
    row.z = e.z[i];
    if (errors) row.standard_error = e.expected_standard_error[i];
    row.penalised =
        std::find(e.penalised.begin(), e.penalised.end(), static_cast<int>(i)) != e.penalised.end();
    r.goodness.push_back(row);
  }
  r.goodness_note = std::string("Maximum likelihood (MCMC): ") +
                    (e.converged ? "converged" : "did not converge") + " in " +
                    std::to_string(e.iterations) + " iterations";
}

// The model of --model, if any, and the metric flags it completes (its directions and direction
// kind where the flags leave them to it).
std::unique_ptr<model::ShapeProcessModel> read_report_model(const ComparisonRequest& request,
                                                            evaluation::MetricOptions& flags) {
  if (request.model.empty()) return nullptr;
  auto model = std::make_unique<model::ShapeProcessModel>(io::read_model(request.model));
  if (flags.directions == 0) flags.directions = model->measurement.directions;
  if (model->measurement.direction == geometry::DirectionKind::centroid)
    flags.direction = geometry::DirectionKind::centroid;
  return model;
}

// Everything the report measures: the exemplar (a seamless tile of few elements measured as a
// repeat of itself: on its own small torus an element's images one period away are the element
// itself, and the contacts and nearest distances they make would go uncounted), the outputs
// against it, and their verdicts.
struct Measured {
  evaluation::EvaluatedScene exemplar;
  std::string exemplar_note;
  evaluation::Evaluation exemplar_eval;
  std::vector<evaluation::EvaluatedScene> outputs;
  std::vector<std::string> labels;  // per output measured
  std::vector<std::string> empty;   // outputs that hold no element
  std::vector<evaluation::Evaluation> evals;
  std::vector<std::vector<evaluation::Verdict>> verdicts;
};

void measure_report(const ComparisonRequest& request, const evaluation::MetricOptions& flags,
                    const model::ShapeProcessModel* model, Measured& m) {
  m.exemplar = evaluation::read_exemplar(request.exemplar, request.reader, flags);
  const geometry::Scene tile = m.exemplar.scene;  // novelty is judged against the drawing itself
  if (m.exemplar.boundary == geometry::Boundary::torus) {
    const int times = geometry::tile_repeats(m.exemplar.scene.elements.size());
    if (times > 1) {
      m.exemplar.scene = geometry::repeat_tile(m.exemplar.scene, times);
      m.exemplar_note = "measured and drawn as a " + std::to_string(times) + " × " +
                        std::to_string(times) + " repeat of the tile";
    }
  }
  m.exemplar_eval = evaluation::evaluate(m.exemplar, flags);
  for (std::size_t k = 0; k < request.outputs.size(); ++k) {
    const std::string& file = request.outputs[k];
    evaluation::EvaluatedScene output =
        evaluation::read_evaluated_scene(file, request.reader, flags.boundary);
    if (output.scene.elements.empty()) {  // a chain that ended empty: named, not measured
      m.empty.push_back(file);
      continue;
    }
    m.outputs.push_back(std::move(output));
    m.labels.push_back(request.labels.empty() ? file : request.labels[k]);
    // Novelty against the drawing itself, not its repeat (whose period may be the output's).
    m.evals.push_back(evaluation::evaluate(m.outputs.back(), flags, &m.exemplar,
                                           &m.exemplar_eval.statistics, &tile));
  }
  evaluation::ExemplarMeasures measured = evaluation::measure_exemplar(
      m.exemplar.scene, m.exemplar.boundary, m.exemplar_eval.statistics, model);
  measured.scene = nullptr;  // novelty is measured above
  for (std::size_t i = 0; i < m.outputs.size(); ++i) {
    evaluation::Judged judged = evaluation::measure_for_verdicts(
        measured, m.outputs[i].scene, m.outputs[i].boundary, m.evals[i].statistics,
        *m.evals[i].comparison, &*m.evals[i].neighbourhood);
    judged.novelty = m.evals[i].novelty;
    m.verdicts.push_back(evaluation::judge(judged));
  }
}

// The model's part of the report: its goodness-of-fit table, the simulation envelopes of the
// nearest distances, and the fit's times.
void add_model(const model::ShapeProcessModel& model, const Measured& m, Report& r) {
  read_goodness(model, r);
  const core::Stopwatch envelopes_watch;
  const evaluation::EnvelopeOptions envelope;
  r.envelopes =
      evaluation::nearest_envelopes(m.exemplar.scene, m.exemplar.boundary, model, envelope);
  r.envelope_samples = envelope.samples;
  r.timings.emplace_back("simulation envelopes", envelopes_watch.seconds());
  if (!model.fit) return;
  const model::FitSeconds& seconds = model.fit->seconds;
  for (const auto& [stage, value] : {std::pair{"measurements", seconds.measurements},
                                     {"optimisation", seconds.optimisation},
                                     {"proxies", seconds.proxies},
                                     {"quadrature", seconds.quadrature}})
    r.timings.emplace_back(std::string("fit: ") + stage, value);
}

// metrics.json: every measure of the exemplar and the outputs, and the outputs' verdicts.
void write_metrics_json(const ComparisonRequest& request, const evaluation::MetricOptions& flags,
                        const Measured& m) {
  nlohmann::json metrics = {{"exemplar", evaluation_json(m.exemplar, m.exemplar_eval)},
                            {"outputs", nlohmann::json::array()},
                            {"options", metric_options_json(flags)}};
  for (std::size_t i = 0; i < m.outputs.size(); ++i) {
    nlohmann::json entry = evaluation_json(m.outputs[i], m.evals[i]);
    entry["summary"] = evaluation::summary(m.verdicts[i]);
    for (const evaluation::Verdict& v : m.verdicts[i])
      entry["verdicts"].push_back({{"check", v.metric},
                                   {"value", v.value},
                                   {"shown", v.shown},
                                   {"rule", v.rule},
                                   {"outcome", evaluation::to_string(v.outcome)},
                                   {"problem", v.problem}});
    metrics["outputs"].push_back(std::move(entry));
  }
  core::write_file_atomically(std::filesystem::path(request.directory) / "metrics.json",
                              [&](std::ostream& f) { f << metrics.dump(2) << '\n'; });
}

}  // namespace

ComparisonReport write_comparison_report(const ComparisonRequest& request) {
  const core::Stopwatch watch;
  evaluation::MetricOptions flags = request.metrics;
  const std::unique_ptr<model::ShapeProcessModel> model = read_report_model(request, flags);
  if (std::filesystem::exists(request.directory) &&
      !std::filesystem::is_directory(request.directory)) {
    throw core::UsageError(request.directory + ": exists and is not a directory");
  }
  Measured m;
  measure_report(request, flags, model.get(), m);
  if (m.outputs.empty())
    throw core::InputError(m.empty.front(), 0,
                           "the output holds no element (its chain ended empty): nothing to "
                           "compare with the exemplar");

  Report r;
  r.exemplar = {request.exemplar, &m.exemplar.scene, &m.exemplar_eval.statistics,
                nullptr,          nullptr,           m.exemplar_note};
  for (std::size_t i = 0; i < m.outputs.size(); ++i) {
    r.outputs.push_back({m.labels[i], &m.outputs[i].scene, &m.evals[i].statistics,
                         &*m.evals[i].comparison, &*m.evals[i].neighbourhood,
                         m.outputs[i].record ? m.outputs[i].record->summary() : std::string(),
                         &m.verdicts[i]});
  }
  r.model = model.get();
  if (model) add_model(*model, m, r);
  r.model_label = request.model;
  r.command = request.command;
  for (const auto& timing : request.timings) r.timings.push_back(timing);
  r.timings.emplace_back("metrics: exemplar", m.exemplar_eval.statistics.seconds);
  for (std::size_t i = 0; i < m.evals.size(); ++i) {
    r.timings.emplace_back("metrics: output " + std::to_string(i + 1),
                           m.evals[i].statistics.seconds);
  }
  std::filesystem::create_directories(request.directory);
  write_metrics_json(request, flags, m);
  r.timings.emplace_back("reading and metrics, in total", watch.seconds());
  write_report(r, request.directory);
  write_verdict_markdown(r, std::filesystem::path(request.directory) / "verdicts.md");
  ComparisonReport result;
  result.empty_outputs = m.empty;
  result.index = (std::filesystem::path(request.directory) / "index.html").string();
  for (std::size_t i = 0; i < m.outputs.size(); ++i) {
    const evaluation::Evaluation& e = m.evals[i];
    OutputSummary summary;
    summary.label = m.labels[i];
    summary.file = m.outputs[i].file;
    summary.verdicts = evaluation::summary(m.verdicts[i]);
    summary.elements = e.statistics.elements();
    summary.colliding_pairs = e.statistics.collisions.pairs.size();
    summary.w1_nearest = e.comparison->all.nearest;
    summary.w1_pairs = e.comparison->all.pairs;
    summary.neighbourhood = e.neighbourhood->normalised;
    result.outputs.push_back(std::move(summary));
  }
  return result;
}

}  // namespace shapeproc::report
