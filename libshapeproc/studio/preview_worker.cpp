// The studio session's worker: the fit, then the preview of the newest revision, again and again.
#include <optional>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/studio/detail/session_shared.hpp"

namespace shapeproc::studio {

namespace {

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The model as `sample` reads it from the export: written and read once (a model built in memory,
// e.g. by a fit, may differ from its file in a coordinate's last bit, and the chain follows every
// bit).
model::ShapeProcessModel as_read_back(const model::ShapeProcessModel& model,
                                      const std::string& file) {
  return io::parse_model(io::model_to_json(model), file);
}

std::string svg_of(const geometry::Scene& scene) {
  std::ostringstream svg;
  io::write_svg(scene, svg, {});
  return svg.str();
}

}  // namespace

void StudioSession::Shared::fit_exemplar() {
  const core::Stopwatch watch;
  fit::ExemplarFitOptions options = input.fit;
  // The fit has no cancellation flag of its own: its progress reports stop it when the session
  // ends.
  auto report = [&](const std::string& stage, long long done, long long total) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (stopping) throw core::Cancelled();
    fit = {stage, done, total, watch.seconds()};
  };
  options.fit.progress = [&](const char* stage, long long done, long long total) {
    report(stage, done, total);
  };
  if (options.likelihood) {
    const int iterations = options.likelihood->max_iterations;
    options.likelihood->progress = [&, iterations](const fit::MleProgress& at) {
      report("maximum likelihood", at.iteration, iterations);
    };
  }
  try {
    fit::ExemplarFit fitted = fit::fit_exemplar(*input.exemplar, options);
    if (input.record_fit) input.record_fit(fitted.result.model);
    const std::lock_guard<std::mutex> lock(mutex);
    history.emplace(std::move(fitted.result.model));
    phase = Phase::ready;
    fit.seconds = watch.seconds();
    ask();
  } catch (const core::Cancelled&) {
  } catch (const std::exception& e) {
    const std::lock_guard<std::mutex> lock(mutex);
    phase = Phase::failed;
    error = e.what();
    changed.notify_all();
  }
}

void StudioSession::Shared::publish(Preview preview) {
  const std::lock_guard<std::mutex> lock(mutex);
  preview.sequence = ++sequence;
  latest = std::move(preview);
  changed.notify_all();
}

void StudioSession::Shared::preview(long long at, model::ShapeProcessModel model, PreviewSpec spec,
                                    Clock::time_point asked,
                                    std::vector<geometry::Element>& on_screen) {
  auto picture = [&](const synthesis::SynthesisResult& result, PreviewStage stage) {
    Preview p;
    p.revision = at;
    p.stage = stage;
    p.svg = svg_of(result.scene);
    p.elements = static_cast<int>(result.scene.elements.size());
    p.steps = result.record.steps;
    p.stationary = result.record.stationary;
    p.seed = spec.seed;
    p.size = spec.size;
    return p;
  };
  // The draft: the picture on screen moved under the edited model.
  std::optional<Preview> draft_shown;
  if (!on_screen.empty()) {
    const synthesis::SynthesisResult draft = sample_draft(model, spec, on_screen, &cancel);
    on_screen = draft.scene.elements;
    draft_shown = picture(draft, PreviewStage::draft);
    draft_shown->seconds = seconds_since(asked);
    publish(*draft_shown);
  }
  // The final chain, stopped by a newer revision or at the time limit (counted from the edit).
  std::atomic<bool> stop{false};
  bool out_of_time = false;
  const Clock::time_point deadline =
      asked + std::chrono::duration_cast<Clock::duration>(
                  std::chrono::duration<double>(input.final_seconds));
  const auto watch = [&] {
    if (cancel) {
      stop = true;
    } else if (Clock::now() >= deadline) {
      out_of_time = true;
      stop = true;
    }
  };
  synthesis::SynthesisRecord record;
  record.command = "sample";
  std::optional<synthesis::SynthesisResult> output;
  try {
    output = sample_output(model, spec, record, &stop, watch);
  } catch (const core::Cancelled&) {
    if (!out_of_time || cancel) throw;
  }
  Preview p;
  if (output) {
    on_screen = output->scene.elements;
    p = picture(*output, PreviewStage::final);
    if (output->scene.elements.empty())
      p.note = "the chain ended empty: the model holds no element";
    if (judge) {
      p.verdicts = judge->judge(output->scene, &model);
      p.summary = p.verdicts.empty() ? std::string() : evaluation::summary(p.verdicts);
    }
  } else {
    // The draft on screen stays, marked as cut.
    if (draft_shown) p = *draft_shown;
    p.revision = at;
    p.stage = PreviewStage::cut;
    p.seed = spec.seed;
    p.size = spec.size;
    p.note = "the final picture's chain needs more than " +
             core::format_number(input.final_seconds) +
             " s: cut short, the draft stays on screen; export samples it in full";
  }
  p.seconds = seconds_since(asked);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    final_output = FinalOutput{at, std::move(model), std::move(output), spec};
  }
  publish(std::move(p));
}

void StudioSession::Shared::run() {
  if (!history) fit_exemplar();
  std::vector<geometry::Element> on_screen;
  std::vector<double> screen_size;
  long long done = 0;
  for (;;) {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return stopping || (history && revision > done); });
    if (stopping) return;
    const long long at = revision;
    const Clock::time_point asked = asked_at;
    model::ShapeProcessModel model = history->recorded(input.source, input.arguments);
    const PreviewSpec spec{size(), seed};
    cancel = false;
    lock.unlock();
    model = as_read_back(model, input.source);
    if (spec.size != screen_size) on_screen.clear();  // a draft continues a picture of its size
    screen_size = spec.size;
    try {
      preview(at, std::move(model), spec, asked, on_screen);
      done = at;
    } catch (const core::Cancelled&) {
      // A newer revision (or the end): the loop takes it.
    } catch (const std::exception& e) {
      Preview failed;
      failed.revision = at;
      failed.stage = PreviewStage::final;
      failed.note = e.what();
      publish(std::move(failed));
      done = at;
    }
  }
}

}  // namespace shapeproc::studio
