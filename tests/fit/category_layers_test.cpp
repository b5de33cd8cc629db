#include "libshapeproc/fit/category_layers.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tests/disc_scene.hpp"

namespace shapeproc::fit {
namespace {

using testing::add_disc;

// Twelve bases, each with a dot inside and one on its rim (every dot on a base), and twelve
// loose discs apart from everything, of the bases' size.
geometry::Scene decorated_bases() {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(600, 300, 0));
  scene.category_index("base");
  scene.category_index("dot");
  scene.category_index("loose");
  for (int k = 0; k < 12; ++k) {
    const double x = 25 + 50 * k, y = k % 2 ? 60 : 140;
    add_disc(scene, x, y, 18, 0);
    add_disc(scene, x + 3, y - 2, 3, 1);   // inside
    add_disc(scene, x + 18, y + 1, 3, 1);  // on the rim
    add_disc(scene, x + 10, k % 2 ? 240 : 200, 17, 2);
  }
  return scene;
}

TEST(CategoryLayers, DotsOnBasesLieALayerAboveThemAndAreAnchored) {
  const FitResult fit = fit_shape_process(decorated_bases(), FitOptions{});
  const model::ShapeProcessModel& m = fit.model;
  EXPECT_EQ(m.categories[0].layer, 0);
  EXPECT_EQ(m.categories[1].layer, 1);
  EXPECT_EQ(m.categories[2].layer, 0);  // the loose discs touch nothing
  EXPECT_EQ(m.categories[1].anchor, 0);
  EXPECT_EQ(m.categories[1].anchor_reach, 0.0);  // every dot overlaps its base
  EXPECT_EQ(m.categories[0].anchor, -1);
  EXPECT_EQ(m.layer_count(), 2);
  const model::Interaction interaction(m);
  EXPECT_TRUE(interaction.sees(1, 0));   // a dot's intensity counts the bases
  EXPECT_FALSE(interaction.sees(0, 1));  // a base's never counts the dots
  EXPECT_TRUE(interaction.sees(0, 2));
  EXPECT_TRUE(interaction.sees(2, 0));
  bool noted = false;
  for (const std::string& note : fit.notes)
    noted = noted || note.find("layer 1: 'dot' placed after 'base'") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(CategoryLayers, AShareAboveOneKeepsOneLayer) {
  FitOptions options;
  options.layer_share = 2.0;
  const FitResult fit = fit_shape_process(decorated_bases(), options);
  EXPECT_EQ(fit.model.layer_count(), 1);
  EXPECT_EQ(fit.model.categories[1].anchor, -1);
}

TEST(CategoryLayers, LayersAndAnchorsSurviveTheModelFile) {
  const FitResult fit = fit_shape_process(decorated_bases(), FitOptions{});
  const model::ShapeProcessModel back = io::parse_model(io::model_to_json(fit.model), "model.json");
  EXPECT_EQ(back.categories[1].layer, 1);
  EXPECT_EQ(back.categories[1].anchor, 0);
  EXPECT_EQ(back.categories[1].anchor_reach, fit.model.categories[1].anchor_reach);
  model::ShapeProcessModel bad = fit.model;
  bad.categories[0].anchor = 1;  // a base anchored to a higher layer
  EXPECT_THROW(model::validate(bad), std::invalid_argument);
}

sample::SampleResult sample_on(const model::ShapeProcessModel& m, std::uint64_t seed) {
  sample::SamplerOptions options;
  options.iterations = 60000;
  options.shift_radius = 10.0;
  const geometry::Domain domain(
      geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(600, 300, 0)), 2,
      geometry::Boundary::torus);
  core::Random random(seed);
  return sample::ShapeProcessSampler(m, domain, options).sample(random);
}

// The layers are placed in turn: the bases and loose discs do not depend on anything of the dots
// (their β, their γ with the bases), and every dot lies on a base.
TEST(CategoryLayers, TheLowerLayerIgnoresTheUpperAndDotsStayOnBases) {
  // The fitted thresholds, layers and anchor, with strengths set by hand (the regular drawing's
  // pseudo-likelihood has no finite maximum): bases and loose discs at 1e-4, dots at 1e-3, every
  // γ 1 but the hard cores.
  model::ShapeProcessModel m = fit_shape_process(decorated_bases(), FitOptions{}).model;
  for (model::CategoryParameters& c : m.categories) c.beta = c.layer == 0 ? 1e-4 : 1e-3;
  for (model::PairInteraction& pair : m.interactions)
    for (model::AxisParameters& axis : pair.axes) axis.gammas.assign(axis.gammas.size(), 1.0);
  model::ShapeProcessModel other = m;
  other.categories[1].beta *= 5.0;
  for (model::AxisParameters& axis :
       other.interactions[static_cast<std::size_t>(other.interaction_index(0, 1))].axes)
    for (double& g : axis.gammas) g = 3.0;
  const auto lower = [](const sample::SampleResult& r) {
    std::vector<geometry::Vec3> out;
    for (const geometry::Element& e : r.scene.elements)
      if (e.category != 1) out.push_back(e.position);
    return out;
  };
  const sample::SampleResult a = sample_on(m, 7), b = sample_on(other, 7);
  const std::vector<geometry::Vec3> la = lower(a), lb = lower(b);
  ASSERT_EQ(la.size(), lb.size());
  for (std::size_t i = 0; i < la.size(); ++i) EXPECT_EQ(la[i], lb[i]);
  int dots = 0;
  const geometry::PairMeasurer measurer(a.scene, m.measurement_options(true));
  for (const geometry::Element& dot : a.scene.elements) {
    if (dot.category != 1) continue;
    ++dots;
    double nearest = 1e9;
    for (const geometry::Element& base : a.scene.elements)
      if (base.category == 0) nearest = std::min(nearest, measurer.measure(dot, base).distance);
    EXPECT_LT(nearest, 0.0);
  }
  EXPECT_GT(dots, 0);
}

// Points: 36 hosts on a jittered grid of spacing 20, each with two visitors within 3 of it. The
// visitors outnumber the hosts and all lie within half the hosts' spacing of one (under
// independence about half would), so they lie a layer above them, anchored within 3.
TEST(CategoryLayers, VisitorPointsAroundHostsAreAnchoredToThem) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(120, 120, 0));
  scene.category_index("host");
  scene.category_index("visitor");
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  core::Random random(11);
  const auto add = [&](double x, double y, int c) {
    geometry::Element e;
    e.position = geometry::Vec3(x, y, 0);
    e.category = c;
    scene.elements.push_back(e);
  };
  for (int k = 0; k < 36; ++k) {
    const double x = 10 + 20 * (k % 6) + random.uniform(-3, 3);
    const double y = 10 + 20 * (k / 6) + random.uniform(-3, 3);
    add(x, y, 0);
    for (int v = 0; v < 2; ++v) {
      const double r = random.uniform(1, 3), angle = random.uniform(0, 6.283185307179586);
      add(x + r * std::cos(angle), y + r * std::sin(angle), 1);
    }
  }
  const FitResult fit = fit_shape_process(scene, FitOptions{});
  const model::ShapeProcessModel& m = fit.model;
  EXPECT_EQ(m.categories[0].layer, 0);
  EXPECT_EQ(m.categories[1].layer, 1);
  EXPECT_EQ(m.categories[1].anchor, 0);
  EXPECT_GT(m.categories[1].anchor_reach, 1.0);
  EXPECT_LE(m.categories[1].anchor_reach, 3.0 + 1e-5);
  // The hosts, fewer, never lie a layer above the visitors.
  EXPECT_EQ(m.categories[0].anchor, -1);
}

}  // namespace
}  // namespace shapeproc::fit
