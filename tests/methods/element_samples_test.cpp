#include "libshapeproc/methods/common/element_samples.hpp"

#include <gtest/gtest.h>

#include "tests/methods/method_scenes.hpp"

namespace shapeproc::methods {
namespace {

TEST(ElementSamples, CompactShapesGetOneSampleAtTheirReferencePosition) {
  geometry::Scene scene = testing::rectangle_lattice(3, 10.0, 4.0, 3.0);
  const std::vector<SampleTemplate> templates = sample_templates(scene, SampleOptions{});
  ASSERT_EQ(templates.size(), 1u);
  ASSERT_EQ(templates[0].offsets.size(), 1u);
  EXPECT_TRUE(templates[0].offsets[0].isZero());
  const ElementSamples samples = place_samples(scene, templates);
  ASSERT_EQ(samples.size(), 9u);
  EXPECT_EQ(samples.first.back(), 9);
  EXPECT_TRUE(samples.positions[4].isApprox(scene.elements[4].position));
}

TEST(ElementSamples, ElongatedShapesGetSamplesAlongTheirAxisOnTheOutline) {
  // A 40 x 4 bar: elongation of its outline about 40/4 · (a thin rectangle's outline spread),
  // well over 2, so several samples, numbered from one end to the other along x.
  const std::vector<Vec3> outline =
      proxy_points(testing::rectangle(40.0, 4.0), 2, geometry::ProxyOptions{});
  EXPECT_GT(elongation(outline, 2), 5.0);
  const SampleTemplate t = sample_template(outline, 2, 5);
  ASSERT_EQ(t.offsets.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    // Stations at −16, −8, 0, 8, 16, each on the outline (|y| = 2).
    EXPECT_NEAR(t.offsets[k].x(), -16.0 + 8.0 * static_cast<double>(k), 0.7) << k;
    EXPECT_NEAR(std::abs(t.offsets[k].y()), 2.0, 1e-9) << k;
  }
}

TEST(ElementSamples, AutomaticCountsFollowElongation) {
  EXPECT_EQ(automatic_sample_count(1.0), 1);
  EXPECT_EQ(automatic_sample_count(1.99), 1);
  EXPECT_EQ(automatic_sample_count(4.0), 5);  // Ma et al.'s bananas: 5 samples
  EXPECT_EQ(automatic_sample_count(50.0), 8);
  EXPECT_EQ(sample_key(5, 2), sample_key(5, 2));
  EXPECT_NE(sample_key(5, 2), sample_key(4, 2));
}

TEST(ElementSamples, ACategoryShareItsCount) {
  geometry::Scene scene = testing::rectangle_lattice(2, 50.0, 40.0, 4.0);
  scene.shapes.push_back(testing::rectangle(30.0, 5.0));
  scene.elements[1].shape = 1;
  const std::vector<SampleTemplate> templates = sample_templates(scene, SampleOptions{});
  EXPECT_EQ(templates[0].offsets.size(), templates[1].offsets.size());
  SampleOptions three;
  three.per_element = 3;
  EXPECT_EQ(sample_templates(scene, three)[1].offsets.size(), 3u);
}

}  // namespace
}  // namespace shapeproc::methods
