#include "libshapeproc/methods/common/element_reconstruction.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/methods/common/orientation_field.hpp"

namespace shapeproc::methods {
namespace {

std::vector<Vec3> template_points() {
  return {Vec3(-10, 1, 0), Vec3(-4, -1, 0), Vec3(3, 2, 0), Vec3(9, 0, 0)};
}

TEST(ElementReconstruction, SimilarityRecoversRotationScaleAndTranslation) {
  const std::vector<Vec3> from = template_points();
  std::vector<Vec3> to;
  for (const Vec3& p : from) to.push_back(Vec3(50, 20, 0) + 1.5 * turn_about_z(p, 0.7));
  const Similarity s = fit_similarity(from, to, 2);
  for (std::size_t i = 0; i < from.size(); ++i) EXPECT_LT((s(from[i]) - to[i]).norm(), 1e-9);
  const double determinant = s.linear.topLeftCorner<2, 2>().determinant();
  EXPECT_NEAR(determinant, 1.5 * 1.5, 1e-9);
}

TEST(ElementReconstruction, InterpolatingSplinePassesThroughTheSamples) {
  const std::vector<Vec3> from = template_points();
  std::vector<Vec3> to = from;
  to[1] += Vec3(0, 3, 0);  // a bent element
  const ThinPlateSpline exact(from, to, 2, true);
  for (std::size_t i = 0; i < from.size(); ++i) EXPECT_LT((exact(from[i]) - to[i]).norm(), 1e-8);
  // The relaxed spline lies between the similarity and the samples.
  const ThinPlateSpline relaxed(from, to, 2, false);
  const Similarity rigid = fit_similarity(from, to, 2);
  const double bent = (to[1] - rigid(from[1])).norm();
  const double left = (to[1] - relaxed(from[1])).norm();
  EXPECT_GT(left, 1e-3);
  EXPECT_LT(left, bent);
}

TEST(ElementReconstruction, CollinearSamplesKeepTheShapeAcrossTheLine) {
  // Samples on a line leave the affine part open: the similarity carries the perpendicular.
  const std::vector<Vec3> from = {Vec3(-10, 0, 0), Vec3(0, 0, 0), Vec3(10, 0, 0)};
  std::vector<Vec3> to;
  for (const Vec3& p : from) to.push_back(turn_about_z(p, 0.5) + Vec3(5, 5, 0));
  const ThinPlateSpline spline(from, to, 2, true);
  const Vec3 off_line(0, 4, 0);
  EXPECT_LT((spline(off_line) - (turn_about_z(off_line, 0.5) + Vec3(5, 5, 0))).norm(), 1e-6);
}

}  // namespace
}  // namespace shapeproc::methods
