#include "libshapeproc/fit/line_quadrature.hpp"

#include <gtest/gtest.h>

#include <map>

#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tests/test_support.hpp"

namespace shapeproc {
namespace {

using geometry::Element;
using geometry::Scene;
using geometry::Vec3;

// The statistics along a line, by brute force: the conditional intensity's statistic at many
// points of the line, each standing for its share of the length.
std::map<std::vector<std::pair<int, int>>, double> sampled(const model::Interaction& interaction,
                                                           const geometry::PairMeasurer& measurer,
                                                           const Scene& scene, const Element& dummy,
                                                           double length, int samples) {
  std::map<std::vector<std::pair<int, int>>, double> measure;
  for (int i = 0; i < samples; ++i) {
    Element at = dummy;
    at.position.x() += (i + 0.5) * length / samples;
    model::InteractionCounts counts;
    for (const Element& other : scene.elements) {
      const model::PairEffect effect = model::pair_effect(interaction, measurer, at, other);
      if (effect.band == model::Interaction::kHardCore) counts.hard_core = true;
      if (effect.band >= 0)
        counts.add(interaction.parameter(at.category, other.category, effect.axis, effect.band));
    }
    if (!counts.hard_core) measure[counts.counts] += length / samples;
  }
  return measure;
}

class LineQuadrature : public ::testing::TestWithParam<std::string> {};

// Along rows across an exemplar, the exact line integral agrees with dense point sampling to the
// sampling's resolution (each transition costs at most one sample spacing).
TEST_P(LineQuadrature, AgreesWithDenseSamplingAlongRows) {
  const Scene scene = io::read_scene(testing::data_path(GetParam()), {});
  fit::FitOptions options;
  options.quadrature = 8;
  const fit::FitResult fitted = fit::fit_shape_process(scene, options);
  const model::Interaction interaction(fitted.model);
  const geometry::PairMeasurer measurer(scene, fitted.model.measurement_options(false));
  fit::LineContext context;
  context.interaction = &interaction;
  context.measurer = &measurer;
  context.data = &scene.elements;
  const double length = scene.window.sizes().x();
  context.tolerance = 1e-7 * length;
  const int samples = 20000;
  for (int row = 0; row < 3; ++row) {
    Element dummy;
    dummy.shape = (row * 7) % static_cast<int>(scene.shapes.size());
    dummy.category = 0;
    dummy.position = scene.window.min();
    dummy.position.y() += (row + 0.37) * scene.window.sizes().y() / 3;
    std::map<std::vector<std::pair<int, int>>, double> exact;
    int transitions = 0;
    for (const fit::LinePiece& piece :
         fit::integrate_line(context, 0, dummy.shape, dummy.position, length)) {
      exact[piece.counts] += piece.length;
      transitions += 2;
    }
    const auto brute = sampled(interaction, measurer, scene, dummy, length, samples);
    std::map<std::vector<std::pair<int, int>>, bool> keys;
    for (const auto& [k, v] : exact) keys[k] = true;
    for (const auto& [k, v] : brute) keys[k] = true;
    double total_difference = 0.0;
    for (const auto& [k, unused] : keys) {
      const double a = exact.count(k) ? exact.at(k) : 0.0;
      const double b = brute.count(k) ? brute.at(k) : 0.0;
      total_difference += std::abs(a - b);
      if (std::abs(a - b) > 0.1) {
        std::string name;
        for (auto [p, c] : k) name += std::to_string(p) + "x" + std::to_string(c) + " ";
        ADD_FAILURE() << "row " << row << " statistic {" << name << "}: line " << a << ", sampled "
                      << b;
      }
    }
    EXPECT_LT(total_difference, (transitions + 20) * length / samples) << "row " << row;
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedExemplars, LineQuadrature,
                         ::testing::Values("svg/dots-random.svg", "svg/dashes-rows.svg",
                                           "svg/crescents-grid.svg"));

}  // namespace
}  // namespace shapeproc
