// The state a studio session shares between the threads that call it and its preview worker,
// under one mutex.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "libshapeproc/studio/edit_history.hpp"
#include "libshapeproc/studio/preview_chain.hpp"
#include "libshapeproc/studio/preview_verdicts.hpp"
#include "libshapeproc/studio/studio_session.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::studio {

using Clock = std::chrono::steady_clock;

// A final preview with what exporting it needs.
struct FinalOutput {
  long long revision = 0;
  model::ShapeProcessModel model;  // as exported: its edits recorded
  // `sample`'s output; empty when the preview's chain was cut short (the export samples it).
  std::optional<synthesis::SynthesisResult> result;
  PreviewSpec spec;
};

struct StudioSession::Shared {
  StudioInput input;
  std::unique_ptr<const PreviewJudge> judge;  // with an exemplar

  mutable std::mutex mutex;
  mutable std::condition_variable changed;  // a revision asked for, a picture published, a stop
  Phase phase = Phase::fitting;
  FitProgress fit;
  std::string error;
  std::optional<EditHistory> history;
  std::uint64_t seed = 1;
  int rerolls = 0;
  bool full = false;
  long long revision = 0;      // the newest asked for
  Clock::time_point asked_at;  // when it was asked for
  long long sequence = 0;
  std::optional<Preview> latest;
  std::optional<FinalOutput> final_output;
  bool stopping = false;
  std::atomic<bool> cancel{false};  // the running chain's: set by a newer revision or a stop
  std::thread worker;

  // Under the mutex: a new revision, cancelling the preview being sampled.
  void ask() {
    ++revision;
    asked_at = Clock::now();
    cancel = true;
    changed.notify_all();
  }
  // Under the mutex: the preview size.
  const std::vector<double>& size() const { return full ? input.full_size : input.preview_size; }

  void run();  // the worker (preview_worker.cpp)
  void fit_exemplar();
  void preview(long long revision, model::ShapeProcessModel model, PreviewSpec spec,
               Clock::time_point asked_at, std::vector<geometry::Element>& on_screen);
  void publish(Preview preview);
};

}  // namespace shapeproc::studio
