#include "libshapeproc/fit/shape_classes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/fit/mcmc_mle.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::fit {
namespace {

// A filled square of side `side`, centred on the origin.
geometry::Shape square(double side) {
  const double h = side / 2;
  geometry::Path2 path;
  const geometry::Vec2 corners[] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (int i = 0; i < 4; ++i)
    path.segments.push_back(geometry::Segment2::line(corners[i], corners[(i + 1) % 4]));
  path.closed = true;
  geometry::Drawable2 drawable;
  drawable.paths.push_back(path);
  return geometry::Shape{geometry::PlanarShape{{drawable}}, ""};
}

// A scene with one element per entry of `sides` (each its own shape, as the readers make them)
// and its model skeleton: one category, the scene's shapes.
struct Fixture {
  geometry::Scene scene;
  model::ShapeProcessModel model;

  explicit Fixture(const std::vector<double>& sides) {
    scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(100, 100, 0));
    scene.categories.push_back({"default"});
    model.categories.push_back({"default", 1.0});
    for (std::size_t i = 0; i < sides.size(); ++i) {
      scene.shapes.push_back(square(sides[i]));
      scene.elements.push_back(
          {static_cast<int>(i), 0, geometry::Vec3(10.0 * static_cast<double>(i), 5, 0)});
      model.shapes.push_back({scene.shapes.back(), 0});
    }
  }
};

// `first` squares of side `a`, then `second` of side `b`.
std::vector<double> two_sizes(int first, double a, int second, double b) {
  std::vector<double> sides(static_cast<std::size_t>(first), a);
  sides.insert(sides.end(), static_cast<std::size_t>(second), b);
  return sides;
}

TEST(ShapeClasses, OneShapeEverywhereNeedsNoClass) {
  Fixture f(std::vector<double>(12, 3.0));
  assign_shape_classes(f.model, f.scene);
  EXPECT_TRUE(f.model.shape_classes.empty());
  for (const model::ModelShape& s : f.model.shapes) EXPECT_EQ(s.shape_class, -1);
}

TEST(ShapeClasses, IdenticalShapesFormClassesWithTheirShares) {
  Fixture f(two_sizes(6, 2.0, 9, 5.0));
  assign_shape_classes(f.model, f.scene);
  ASSERT_EQ(f.model.shape_classes.size(), 2u);
  EXPECT_EQ(f.model.shape_classes[0].label, "identical shapes");
  EXPECT_EQ(f.model.shapes[0].shape_class, f.model.shapes[5].shape_class);
  EXPECT_NE(f.model.shapes[0].shape_class, f.model.shapes[6].shape_class);
  const int small = f.model.shapes[0].shape_class;
  EXPECT_DOUBLE_EQ(f.model.shape_classes[static_cast<std::size_t>(small)].weight, 6.0 / 15.0);
  EXPECT_NO_THROW(model::validate(f.model));
}

TEST(ShapeClasses, TooManyShapesAreGroupedBySize) {
  // 12 different sizes, one element each: 12 / 5 = 2 size groups of 6, small and large apart.
  std::vector<double> sides;
  for (int i = 0; i < 12; ++i) sides.push_back(1.0 + i);
  Fixture f(sides);
  assign_shape_classes(f.model, f.scene);
  ASSERT_EQ(f.model.shape_classes.size(), 2u);
  EXPECT_EQ(f.model.shape_classes[0].label, "size 1 of 2");
  for (int i = 0; i < 12; ++i)
    EXPECT_EQ(f.model.shapes[static_cast<std::size_t>(i)].shape_class, i < 6 ? 0 : 1) << i;
  EXPECT_DOUBLE_EQ(f.model.shape_classes[0].weight, 0.5);
}

// A group of identical shapes joins the class where most of its elements fall: 5 small, 11
// middle and 3 large (19 elements, 3 shares of 6.3) make small | middle and large (the large
// ones, too few for a class, join the middle ones), not one class for all.
TEST(ShapeClasses, AGroupGoesWhereMostOfItsElementsFall) {
  std::vector<double> sides = two_sizes(5, 1.0, 11, 4.0);
  sides.insert(sides.end(), 3, 6.0);
  Fixture f(sides);
  assign_shape_classes(f.model, f.scene);
  ASSERT_EQ(f.model.shape_classes.size(), 2u);
  for (int i = 0; i < 19; ++i)
    EXPECT_EQ(f.model.shapes[static_cast<std::size_t>(i)].shape_class, i < 5 ? 0 : 1) << i;
  EXPECT_DOUBLE_EQ(f.model.shape_classes[0].weight, 5.0 / 19.0);
}

// The sampler draws a birth's shape by its class weight: with no interaction, the class counts of
// a sample are Poisson with means β |W| w_k, here 0.25 and 0.75 of 200 (within 4 standard
// deviations), and its t(x) carries them after the category count.
TEST(ShapeClasses, SamplesKeepTheClassShares) {
  Fixture f(two_sizes(6, 2.0, 6, 4.0));
  assign_shape_classes(f.model, f.scene);
  ASSERT_EQ(f.model.shape_classes.size(), 2u);
  f.model.shape_classes[0].weight = 0.25;
  f.model.shape_classes[1].weight = 0.75;
  f.model.categories[0].beta = 200.0 / 10000.0;
  f.model.measurement.directions = 1;
  const geometry::Domain domain =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::torus);
  sample::SamplerOptions options;
  options.iterations = 20000;
  core::Random random(3);
  const sample::SampleResult r = sample::sample_shape_process(f.model, domain, options, random);
  ASSERT_EQ(r.statistics.size(), 3u);
  EXPECT_NEAR(r.statistics[1], 50.0, 4 * std::sqrt(50.0));
  EXPECT_NEAR(r.statistics[2], 150.0, 4 * std::sqrt(150.0));
  EXPECT_DOUBLE_EQ(r.statistics[0], r.statistics[1] + r.statistics[2]);
}

// Without interaction the MLE is closed: β = n / |W| and each class's weight its share n_k / n.
TEST(ShapeClasses, PoissonMaximumLikelihoodIsTheShares) {
  Fixture f(two_sizes(6, 2.0, 9, 5.0));
  assign_shape_classes(f.model, f.scene);
  const geometry::Domain window =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::open);
  const MleResult mle = maximise_likelihood(f.model, window, {15.0, 6.0, 9.0}, MleOptions{});
  ASSERT_TRUE(mle.converged);
  const model::ShapeProcessModel fitted = with_estimates(f.model, mle);
  EXPECT_NEAR(fitted.categories[0].beta, 15.0 / 10000.0, 1e-15);
  EXPECT_NEAR(fitted.shape_classes[0].weight, 6.0 / 15.0, 1e-12);
  EXPECT_NEAR(fitted.shape_classes[1].weight, 9.0 / 15.0, 1e-12);
}

TEST(ShapeClasses, ValidationNamesTheField) {
  Fixture f(two_sizes(5, 2.0, 5, 4.0));
  assign_shape_classes(f.model, f.scene);
  ASSERT_EQ(f.model.shape_classes.size(), 2u);
  f.model.shape_classes[1].weight = -1;
  try {
    model::validate(f.model);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shape_classes[1].weight"), std::string::npos) << e.what();
  }
  f.model.shape_classes[1].weight = 1;
  f.model.shapes[0].shape_class = 7;
  EXPECT_THROW(model::validate(f.model), std::invalid_argument);
}

}  // namespace
}  // namespace shapeproc::fit
