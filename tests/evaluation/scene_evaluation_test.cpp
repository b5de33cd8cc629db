// Scenes as they are judged: the boundary each is read with, the options it is measured with,
// and an exemplar against itself (every distance zero, every element a copy).
#include "libshapeproc/evaluation/scene_evaluation.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::evaluation {
namespace {

const std::string kDots = testing::data_path("svg/dots-random.svg").string();

TEST(SceneEvaluation, ReadsWithTheBoundaryChosen) {
  io::ReaderOptions reader;
  EXPECT_EQ(read_evaluated_scene(kDots, reader, BoundaryChoice::automatic).boundary,
            geometry::Boundary::open);
  EXPECT_EQ(read_evaluated_scene(kDots, reader, BoundaryChoice::torus).boundary,
            geometry::Boundary::torus);
  const EvaluatedScene plain = read_evaluated_scene(kDots, reader, BoundaryChoice::open);
  EXPECT_FALSE(plain.record.has_value());
  EXPECT_EQ(plain.file, kDots);
  // A seamless tile is one period of a torus, unless the options say open.
  reader.tile = true;
  EXPECT_EQ(read_evaluated_scene(kDots, reader, BoundaryChoice::automatic).boundary,
            geometry::Boundary::torus);
  EXPECT_EQ(read_evaluated_scene(kDots, reader, BoundaryChoice::open).boundary,
            geometry::Boundary::open);
  // The exemplar's side: a torus given for the outputs is not the exemplar's.
  MetricOptions options;
  options.boundary = BoundaryChoice::torus;
  EXPECT_EQ(read_exemplar(kDots, {}, options).boundary, geometry::Boundary::open);
}

TEST(SceneEvaluation, RefusesAnEmptySceneNamingIt) {
  const testing::TempDir dir;
  const auto empty = dir.write(
      "empty.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"/>");
  try {
    read_evaluated_scene(empty.string(), {}, BoundaryChoice::automatic);
    FAIL() << "an empty scene was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.svg"), std::string::npos) << e.what();
  }
}

TEST(SceneEvaluation, StatisticsOptionsFollowTheSceneAndRefuseNonsense) {
  const EvaluatedScene scene = read_evaluated_scene(kDots, {}, BoundaryChoice::torus);
  MetricOptions options;
  options.range = 12.5;
  options.direction = geometry::DirectionKind::centroid;
  metrics::StatisticsOptions o = statistics_options(scene, options, 0.0);
  EXPECT_TRUE(o.measurement.periodic);
  EXPECT_EQ(o.range, 12.5);
  EXPECT_EQ(o.measurement.direction, geometry::DirectionKind::centroid);
  EXPECT_EQ(o.measurement.directions, geometry::directions_or_default(0, 2));
  EXPECT_EQ(statistics_options(scene, options, 30.0).range, 30.0);  // the reference's range wins
  options.range = -1;
  EXPECT_THROW(statistics_options(scene, options, 0.0), core::ArgumentError);
  options.range = 0;
  options.proxy_tolerance = 1.5;
  EXPECT_THROW(statistics_options(scene, options, 0.0), core::ArgumentError);
  options.proxy_tolerance = 0.1;
  options.directions = 3;  // 2D bins come in even numbers
  EXPECT_THROW(statistics_options(scene, options, 0.0), core::UsageError);
}

TEST(SceneEvaluation, AnExemplarAgainstItselfIsACopyAtZeroDistance) {
  const EvaluatedScene scene = read_evaluated_scene(kDots, {}, BoundaryChoice::automatic);
  const Evaluation alone = evaluate(scene, {});
  EXPECT_FALSE(alone.comparison.has_value());
  EXPECT_FALSE(alone.novelty.has_value());
  EXPECT_EQ(alone.statistics.elements(), static_cast<int>(scene.scene.elements.size()));
  const Evaluation against = evaluate(scene, {}, &scene, &alone.statistics);
  ASSERT_TRUE(against.comparison && against.neighbourhood && against.novelty);
  EXPECT_DOUBLE_EQ(against.comparison->all.nearest, 0.0);
  EXPECT_DOUBLE_EQ(against.comparison->all.pairs, 0.0);
  EXPECT_NEAR(against.neighbourhood->mean, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(against.novelty->output.copy, 1.0);
  EXPECT_EQ(against.statistics.range, alone.statistics.range);
}

TEST(SceneEvaluation, RefusesAReferenceOfAnotherDimension) {
  const EvaluatedScene flat = read_evaluated_scene(kDots, {}, BoundaryChoice::automatic);
  const EvaluatedScene solid = read_evaluated_scene(testing::data_path("mesh/pebbles.obj").string(),
                                                    {}, BoundaryChoice::automatic);
  const Evaluation reference = evaluate(solid, {});
  EXPECT_THROW(evaluate(flat, {}, &solid, &reference.statistics), core::UsageError);
}

}  // namespace
}  // namespace shapeproc::evaluation
