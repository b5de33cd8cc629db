#include "libshapeproc/methods/common/position_assignment.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/random.hpp"

namespace shapeproc::methods {
namespace {

// A jittered 6 x 6 lattice whose predictions are the exact lattice offsets between neighbours:
// the least-squares positions are the lattice, up to one common translation.
void check_lattice(geometry::Boundary boundary) {
  const int n = 6;
  const double a = 10.0;
  const geometry::Domain domain = geometry::Domain::from_sizes({n * a, n * a}, boundary);
  core::Random random(3);
  std::vector<Vec3> lattice, jittered;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      lattice.emplace_back((i + 0.5) * a, (j + 0.5) * a, 0.0);
      jittered.push_back(lattice.back() + Vec3(random.uniform(-2, 2), random.uniform(-2, 2), 0.0));
    }
  std::vector<Prediction> predictions;
  for (std::size_t c = 0; c < lattice.size(); ++c)
    for (std::size_t o = 0; o < lattice.size(); ++o) {
      const Vec3 t = domain.minimum_image(lattice[o] - lattice[c]);
      if (o != c && t.norm() < 1.5 * a)
        predictions.push_back({static_cast<int>(c), static_cast<int>(o), t});
    }
  EXPECT_GT(position_energy(jittered, predictions, domain), 1.0);
  const std::vector<Vec3> d = solve_positions(jittered, predictions, domain);
  std::vector<Vec3> solved(jittered.size());
  Vec3 shift = Vec3::Zero();
  for (std::size_t i = 0; i < jittered.size(); ++i) {
    solved[i] = jittered[i] + d[i];
    shift += domain.minimum_image(solved[i] - lattice[i]);
  }
  shift /= static_cast<double>(lattice.size());
  for (std::size_t i = 0; i < lattice.size(); ++i)
    EXPECT_LT(domain.minimum_image(solved[i] - lattice[i] - shift).norm(), 1e-4) << i;
  EXPECT_LT(position_energy(solved, predictions, domain), 1e-6);
  // The ridge keeps the mean displacement at zero.
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : d) mean += v;
  EXPECT_LT((mean / static_cast<double>(d.size())).norm(), 1e-6);
}

TEST(PositionAssignment, ReproducesALatticeFromExactPredictions) {
  check_lattice(geometry::Boundary::open);
}

TEST(PositionAssignment, ReproducesALatticeOnATorus) { check_lattice(geometry::Boundary::torus); }

TEST(PositionAssignment, ConflictingPredictionsMeetHalfWay) {
  // Two predictions of the same pair, 4 and 6 apart: least squares puts them 5 apart.
  const geometry::Domain domain =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::open);
  const std::vector<Vec3> p = {Vec3(10, 10, 0), Vec3(20, 10, 0)};
  const std::vector<Prediction> predictions = {{0, 1, Vec3(4, 0, 0)}, {1, 0, Vec3(-6, 0, 0)}};
  const std::vector<Vec3> d = solve_positions(p, predictions, domain);
  EXPECT_NEAR((p[1] + d[1] - p[0] - d[0]).x(), 5.0, 1e-5);
  EXPECT_NEAR(position_energy({p[0] + d[0], p[1] + d[1]}, predictions, domain), 2.0, 1e-4);
}

}  // namespace
}  // namespace shapeproc::methods
