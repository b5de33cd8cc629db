#include "libshapeproc/compare/position_assignment.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::compare {

std::vector<Vec3> solve_positions(const std::vector<Vec3>& positions,
                                  const std::vector<Prediction>& predictions,
                                  const geometry::Domain& domain,
                                  const std::vector<double>& anchors) {
  const auto n = static_cast<Eigen::Index>(positions.size());
  std::vector<Vec3> displacement(positions.size(), Vec3::Zero());
  if (n == 0 || predictions.empty()) return displacement;
  const double ridge =
      kRidge * (2.0 * static_cast<double>(predictions.size()) / static_cast<double>(n));

  // Each prediction (a → b, t) is the residual (d_b − d_a) − r with r = t − (p_b − p_a).
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(4 * predictions.size() + positions.size());
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  for (const Prediction& p : predictions) {
    const auto a = static_cast<Eigen::Index>(p.centre), b = static_cast<Eigen::Index>(p.neighbour);
    if (a == b) continue;
    const Vec3 residual = p.offset - domain.minimum_image(positions[static_cast<std::size_t>(b)] -
                                                          positions[static_cast<std::size_t>(a)]);
    const double w = p.weight;
    triplets.emplace_back(a, a, w);
    triplets.emplace_back(b, b, w);
    triplets.emplace_back(a, b, -w);
    triplets.emplace_back(b, a, -w);
    rhs.row(b) += w * residual.transpose();
    rhs.row(a) -= w * residual.transpose();
  }
  for (Eigen::Index i = 0; i < n; ++i)
    triplets.emplace_back(i, i,
                          ridge + (anchors.empty() ? 0.0 : anchors[static_cast<std::size_t>(i)]));
  Eigen::SparseMatrix<double> system(n, n);
  system.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success)
    throw core::ArgumentError("neighbourhood EM", "the position system could not be factorised");
  const Eigen::MatrixXd d = solver.solve(rhs);
  for (Eigen::Index i = 0; i < n; ++i)
    displacement[static_cast<std::size_t>(i)] = d.row(i).transpose();
  return displacement;
}

double position_energy(const std::vector<Vec3>& positions,
                       const std::vector<Prediction>& predictions, const geometry::Domain& domain) {
  double sum = 0.0;
  for (const Prediction& p : predictions) {
    const Vec3 offset = domain.minimum_image(positions[static_cast<std::size_t>(p.neighbour)] -
                                             positions[static_cast<std::size_t>(p.centre)]);
    sum += p.weight * (offset - p.offset).squaredNorm();
  }
  return sum;
}

}  // namespace shapeproc::compare
