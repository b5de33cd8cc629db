#include "libshapeproc/studio/edit_history.hpp"

#include <utility>

namespace shapeproc::studio {

namespace {

// States kept behind the cursor: enough for any session of dragging, bounded in memory (a model
// is a few kilobytes to a few megabytes with detailed shapes).
constexpr std::size_t kMaxStates = 200;

}  // namespace

EditHistory::EditHistory(model::ShapeProcessModel fitted) {
  states_.push_back({std::move(fitted), {}});
}

void EditHistory::push(State state) {
  states_.resize(at_ + 1);
  states_.push_back(std::move(state));
  // The fit stays first (reset's target); the oldest edits go.
  if (states_.size() > kMaxStates) states_.erase(states_.begin() + 1);
  at_ = states_.size() - 1;
}

void EditHistory::apply(const ModelEdit& edit) {
  State next{apply_edit(current(), edit), edits()};
  next.edits.push_back(describe(edit, current()));
  push(std::move(next));
}

bool EditHistory::undo() {
  if (!can_undo()) return false;
  --at_;
  return true;
}

bool EditHistory::redo() {
  if (!can_redo()) return false;
  ++at_;
  return true;
}

bool EditHistory::reset() {
  if (edits().empty()) return false;
  push(states_.front());
  return true;
}

model::ShapeProcessModel EditHistory::recorded(const std::string& from,
                                               const std::vector<std::string>& arguments) const {
  model::ShapeProcessModel m = current();
  if (edits().empty()) return m;
  if (!m.fit) m.fit.emplace();
  m.fit->edits.push_back({from, arguments, edits()});
  return m;
}

}  // namespace shapeproc::studio
