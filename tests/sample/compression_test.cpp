// The compressing burn-in's schedule: its phases and boosts, exactly, and the scaled hard cores.
#include "libshapeproc/sample/compression.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/move_counts.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::sample {
namespace {

TEST(Compression, BoostedThenReleasedLinearlyThenDone) {
  CompressionOptions options;
  options.burn_in_kind = model::BurnIn::compressing;
  options.release_steps = 100;
  CompressionSchedule schedule(options);
  EXPECT_DOUBLE_EQ(schedule.log_boost(), options.log_boost);
  for (long long step = 1; step < 100; ++step) schedule.after_step(step, 10);
  EXPECT_DOUBLE_EQ(schedule.log_boost(), options.log_boost);  // still the first phase
  schedule.after_step(100, 10);
  EXPECT_EQ(schedule.compressed_for(), 100);
  schedule.after_step(150, 10);  // half-way through the release
  EXPECT_DOUBLE_EQ(schedule.log_boost(), options.log_boost * 0.5);
  EXPECT_FALSE(schedule.done());
  schedule.after_step(200, 10);
  EXPECT_TRUE(schedule.done());
  EXPECT_EQ(schedule.finished_at(), 200);
  EXPECT_DOUBLE_EQ(schedule.log_boost(), 0.0);
}

TEST(Compression, StageStepsFollowTheCountAndOffMeansNoBoost) {
  CompressionOptions options;
  EXPECT_EQ(options.stage_steps(10), CompressionOptions::kLeastStageSteps);
  EXPECT_EQ(options.stage_steps(1000), 1000 * CompressionOptions::kStepsPerElement);
  options.steps = 77;
  EXPECT_EQ(options.stage_steps(1000), 77);
  const CompressionSchedule off(CompressionOptions{});
  EXPECT_TRUE(off.done());
  EXPECT_DOUBLE_EQ(off.log_boost(), 0.0);
  CompressionOptions bad;
  bad.start_scale = 0.0;
  EXPECT_THROW(check_compression(bad), core::ArgumentError);
}

TEST(Compression, OnlyTheHardCoresAreScaled) {
  const model::ShapeProcessModel model = io::parse_model(testing::kSquaresModel, "squares.json");
  const model::ShapeProcessModel half = with_scaled_hard_cores(model, 0.5);
  for (std::size_t p = 0; p < model.interactions.size(); ++p)
    for (std::size_t a = 0; a < model.interactions[p].axes.size(); ++a) {
      const auto& before = model.interactions[p].axes[a].thresholds;
      const auto& after = half.interactions[p].axes[a].thresholds;
      ASSERT_EQ(before.size(), after.size());
      for (std::size_t k = 0; k < before.size(); ++k)
        EXPECT_DOUBLE_EQ(after[k], k == 0 ? before[k] * 0.5 : before[k]);
    }
  EXPECT_THROW(with_scaled_hard_cores(model, 1.5), core::ArgumentError);
}

TEST(MoveCounts, AddUp) {
  MoveCounts a{1, 2, 3, 4, 5, 6}, b{10, 20, 30, 40, 50, 60};
  a += b;
  EXPECT_EQ(a.births_accepted, 11);
  EXPECT_EQ(a.births_proposed, 22);
  EXPECT_EQ(a.deaths_accepted, 33);
  EXPECT_EQ(a.deaths_proposed, 44);
  EXPECT_EQ(a.shifts_accepted, 55);
  EXPECT_EQ(a.shifts_proposed, 66);
}

}  // namespace
}  // namespace shapeproc::sample
