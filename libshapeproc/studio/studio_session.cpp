#include "libshapeproc/studio/studio_session.hpp"

#include <cmath>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/studio/detail/session_shared.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"

namespace shapeproc::studio {

namespace {

void check_size(const std::vector<double>& size, const char* which) {
  if (size.size() != 2 || !(size[0] > 0) || !(size[1] > 0) || !std::isfinite(size[0]) ||
      !std::isfinite(size[1]))
    throw core::ArgumentError(
        "studio", std::string("the ") + which + " size must be two positive numbers W,H");
}

}  // namespace

StudioSession::StudioSession(StudioInput input) : shared_(std::make_unique<Shared>()) {
  if (!input.model && !input.exemplar)
    throw core::ArgumentError("studio", "give a model or an exemplar");
  if ((input.model && input.model->dimension != 2) ||
      (input.exemplar && input.exemplar->dimension != 2))
    throw core::ArgumentError("studio", "previews are drawn in 2D: this is a 3D model");
  check_size(input.preview_size, "preview");
  check_size(input.full_size, "full");
  Shared& s = *shared_;
  s.seed = input.seed;
  if (input.exemplar) s.judge = std::make_unique<PreviewJudge>(*input.exemplar, input.tile);
  if (input.model) {
    s.history.emplace(*input.model);
    s.phase = Phase::ready;
    s.revision = 1;
    s.asked_at = Clock::now();
  }
  s.input = std::move(input);
  s.worker = std::thread([&s] { s.run(); });
}

StudioSession::~StudioSession() { close(); }

void StudioSession::close() {
  {
    const std::lock_guard<std::mutex> lock(shared_->mutex);
    shared_->stopping = true;
    shared_->cancel = true;
    shared_->changed.notify_all();
  }
  if (shared_->worker.joinable()) shared_->worker.join();
}

StudioState StudioSession::state() const {
  const Shared& s = *shared_;
  const std::lock_guard<std::mutex> lock(s.mutex);
  StudioState state;
  state.phase = s.phase;
  state.fit = s.fit;
  state.error = s.error;
  if (s.history) {
    state.model = s.history->current();
    state.edits = s.history->edits();
    state.can_undo = s.history->can_undo();
    state.can_redo = s.history->can_redo();
  }
  state.seed = s.seed;
  state.full = s.full;
  state.size = s.size();
  state.revision = s.revision;
  state.has_exemplar = s.input.exemplar.has_value();
  return state;
}

std::string StudioSession::exemplar_svg() const {
  if (!shared_->input.exemplar) return {};
  std::ostringstream svg;
  io::write_svg(*shared_->input.exemplar, svg, {});
  return svg.str();
}

namespace {

EditHistory& fitted_history(std::optional<EditHistory>& history) {
  if (!history) throw core::UsageError("the model is still being fitted");
  return *history;
}

}  // namespace

void StudioSession::edit(const ModelEdit& edit) {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  fitted_history(shared_->history).apply(edit);
  shared_->ask();
}

bool StudioSession::undo() {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  const bool done = fitted_history(shared_->history).undo();
  if (done) shared_->ask();
  return done;
}

bool StudioSession::redo() {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  const bool done = fitted_history(shared_->history).redo();
  if (done) shared_->ask();
  return done;
}

bool StudioSession::reset() {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  const bool done = fitted_history(shared_->history).reset();
  if (done) shared_->ask();
  return done;
}

void StudioSession::reroll_seed() {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  fitted_history(shared_->history);
  // A new seed from the session's first, reproducibly: the n-th reroll is its n-th chain seed.
  shared_->seed = synthesis::chain_seed(shared_->input.seed, ++shared_->rerolls);
  shared_->ask();
}

void StudioSession::set_seed(std::uint64_t seed) {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  fitted_history(shared_->history);
  shared_->seed = seed;
  shared_->ask();
}

void StudioSession::set_full_size(bool full) {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  fitted_history(shared_->history);
  if (shared_->full == full) return;
  shared_->full = full;
  shared_->ask();
}

std::optional<Preview> StudioSession::wait_preview(long long after,
                                                   std::chrono::milliseconds timeout) const {
  const Shared& s = *shared_;
  std::unique_lock<std::mutex> lock(s.mutex);
  s.changed.wait_for(lock, timeout,
                     [&] { return s.stopping || (s.latest && s.latest->sequence > after); });
  if (s.latest && s.latest->sequence > after) return s.latest;
  return std::nullopt;
}

}  // namespace shapeproc::studio
