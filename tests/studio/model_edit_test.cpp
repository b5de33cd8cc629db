#include "libshapeproc/studio/model_edit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/studio/edit_history.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::studio {
namespace {

model::ShapeProcessModel squares() {
  return io::parse_model(testing::kSquaresModel, "squares.json");
}

TEST(StudioEdits, GammaOfOneAxisOrEveryAxis) {
  const model::ShapeProcessModel m = squares();
  ModelEdit edit{EditKind::gamma, 0, 2, 0, false, 3.0};
  const model::ShapeProcessModel one = apply_edit(m, edit);
  EXPECT_EQ(one.interactions[0].axes[2].gammas[0], 3.0);
  EXPECT_EQ(one.interactions[0].axes[1].gammas[0], 0.5);
  EXPECT_EQ(describe(edit, m), "gamma 0:2:1=3");
  edit.every_axis = true;
  const model::ShapeProcessModel all = apply_edit(m, edit);
  for (const auto& axis : all.interactions[0].axes) EXPECT_EQ(axis.gammas[0], 3.0);
  EXPECT_EQ(describe(edit, m), "gamma 0:*:1=3");
  EXPECT_EQ(m.interactions[0].axes[2].gammas[0], 0.5);  // the model given is never changed
}

TEST(StudioEdits, ThresholdsBetaClassesAndScaling) {
  const model::ShapeProcessModel m = squares();
  const ModelEdit threshold{EditKind::threshold, 0, 0, 1, false, 7.5};
  EXPECT_EQ(apply_edit(m, threshold).interactions[0].axes[0].thresholds[1], 7.5);
  EXPECT_EQ(describe(threshold, m), "threshold 0:0:1=7.5");
  const ModelEdit beta{EditKind::beta, 0, 0, 0, false, 0.4};
  EXPECT_EQ(apply_edit(m, beta).categories[0].beta, 0.4);
  EXPECT_EQ(describe(beta, m), "beta squares=0.4");
  const ModelEdit scale{EditKind::scale_thresholds, 0, 0, 0, false, 2.0};
  EXPECT_EQ(apply_edit(m, scale).interactions[0].axes[2].thresholds, (std::vector<double>{16, 20}));
  const ModelEdit isotropic{EditKind::isotropic, 0, 0, 0, false, 0.0};
  EXPECT_EQ(apply_edit(m, isotropic).interactions[0].axes.size(), 1u);
  EXPECT_EQ(describe(isotropic, m), "isotropic");
}

TEST(StudioEdits, RefusesWhatTheModelCannotTake) {
  const model::ShapeProcessModel m = squares();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto refused = [&](ModelEdit edit) {
    EXPECT_THROW(apply_edit(m, edit), core::ArgumentError) << describe(edit, m);
  };
  refused({EditKind::gamma, 0, 0, 0, false, nan});
  refused({EditKind::gamma, 0, 0, 0, false, -1.0});
  refused({EditKind::gamma, 7, 0, 0, false, 1.0});      // no pair 7
  refused({EditKind::gamma, 0, 9, 0, false, 1.0});      // no axis 9
  refused({EditKind::gamma, 0, 0, 4, false, 1.0});      // no band 5
  refused({EditKind::threshold, 0, 0, 0, false, 9.0});  // δ0 above δ1
  refused({EditKind::beta, 0, 0, 0, false, 0.0});
  refused({EditKind::beta, 0, 0, 3, false, 1.0});          // no category 3
  refused({EditKind::class_weight, 0, 0, 0, false, 1.0});  // no classes
  refused({EditKind::scale_thresholds, 0, 0, 0, false, std::numeric_limits<double>::infinity()});
}

TEST(StudioEditHistory, UndoRedoResetAndTheRecord) {
  EditHistory history(squares());
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.reset());  // already the fit
  history.apply({EditKind::gamma, 0, 0, 0, false, 2.0});
  history.apply({EditKind::beta, 0, 0, 0, false, 0.3});
  EXPECT_EQ(history.edits(), (std::vector<std::string>{"gamma 0:0:1=2", "beta squares=0.3"}));
  EXPECT_THROW(history.apply({EditKind::gamma, 0, 0, 0, false, -2.0}), core::ArgumentError);
  EXPECT_EQ(history.edits().size(), 2u);  // a refused edit changes nothing
  EXPECT_TRUE(history.undo());
  EXPECT_EQ(history.current().categories[0].beta, 0.2);
  EXPECT_TRUE(history.redo());
  EXPECT_EQ(history.current().categories[0].beta, 0.3);
  EXPECT_FALSE(history.redo());
  EXPECT_TRUE(history.undo());
  history.apply({EditKind::gamma, 0, 1, 0, false, 4.0});  // drops the undone beta
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.edits(), (std::vector<std::string>{"gamma 0:0:1=2", "gamma 0:1:1=4"}));
  EXPECT_TRUE(history.reset());
  EXPECT_TRUE(history.edits().empty());
  EXPECT_EQ(history.current().interactions[0].axes[0].gammas[0], 0.5);
  EXPECT_TRUE(history.undo());  // the reset is undone like an edit
  EXPECT_EQ(history.current().interactions[0].axes[1].gammas[0], 4.0);
  const model::ShapeProcessModel recorded =
      history.recorded("squares.json", {"shapeproc", "studio"});
  ASSERT_TRUE(recorded.fit);
  ASSERT_EQ(recorded.fit->edits.size(), 1u);
  EXPECT_EQ(recorded.fit->edits[0].from, "squares.json");
  EXPECT_EQ(recorded.fit->edits[0].edits, history.edits());
}

}  // namespace
}  // namespace shapeproc::studio
