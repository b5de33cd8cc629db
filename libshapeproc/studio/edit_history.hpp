// The studio's edits of a fitted model, with undo and redo: a line of states from the fit, each
// the model after one more edit (or after a reset to the fit), and a cursor on it. A new edit
// drops the states after the cursor, as an editor's redo does.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/studio/model_edit.hpp"

namespace shapeproc::studio {

class EditHistory {
 public:
  explicit EditHistory(model::ShapeProcessModel fitted);

  // The model as edited so far, and the edits that made it from the fit, as `edit` words them.
  const model::ShapeProcessModel& current() const { return states_[at_].model; }
  const std::vector<std::string>& edits() const { return states_[at_].edits; }
  const model::ShapeProcessModel& fitted() const { return states_.front().model; }

  // Applies `edit` to the current model (apply_edit: throws core::ArgumentError, and then nothing
  // changes).
  void apply(const ModelEdit& edit);
  // One state back or forward; false (and nothing changes) where there is none.
  bool undo();
  bool redo();
  // The fit again, as a state of its own (undone like an edit); false where the current model is
  // the fit already.
  bool reset();

  bool can_undo() const { return at_ > 0; }
  bool can_redo() const { return at_ + 1 < states_.size(); }

  // The current model as it is exported: its fit record lists the edits, as `edit` records them,
  // made by `arguments` (the studio's command line) from the model of `from`.
  model::ShapeProcessModel recorded(const std::string& from,
                                    const std::vector<std::string>& arguments) const;

 private:
  struct State {
    model::ShapeProcessModel model;
    std::vector<std::string> edits;
  };
  void push(State state);
  std::vector<State> states_;
  std::size_t at_ = 0;
};

}  // namespace shapeproc::studio
