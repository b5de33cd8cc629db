#include "libshapeproc/fit/detail/level_set_chords.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

namespace shapeproc::fit {

namespace {

// ξ on the level set at η (|k η| ≤ 1 within the clamp).
double arc(const LevelSet& set, double eta) {
  const double k = set.curvature;
  const double kk = std::min(1.0, k * k * eta * eta);
  // (1 − √(1 − k²η²))/k, written without cancellation.
  return set.level - k * eta * eta / (1.0 + std::sqrt(1.0 - kk));
}

// Where along η the arc lies within the cell: from the first to the last of the samples inside,
// each end refined by bisection against its outside neighbour. The whole diagonal when no sample
// is inside (a level set grazing a corner).
std::pair<double, double> span_in_cell(const LevelSet& set, double hx, double hy) {
  const double corner = std::hypot(hx, hy);
  const double tx = -set.ny, ty = set.nx;
  const auto inside = [&](double eta) {
    const double xi = arc(set, eta);
    return std::abs(xi * set.nx + eta * tx) <= hx && std::abs(xi * set.ny + eta * ty) <= hy;
  };
  constexpr int kSamples = 16;
  const auto at = [&](int i) { return -corner + 2 * corner * i / kSamples; };
  int first = -1, last = -1;
  for (int i = 0; i <= kSamples; ++i) {
    if (!inside(at(i))) continue;
    if (first < 0) first = i;
    last = i;
  }
  if (first < 0) return {-corner, corner};
  const auto refine = [&](double in, double out) {
    for (int step = 0; step < 20; ++step) {
      const double mid = 0.5 * (in + out);
      (inside(mid) ? in : out) = mid;
    }
    return in;
  };
  const double low = first > 0 ? refine(at(first), at(first - 1)) : at(first);
  const double high = last < kSamples ? refine(at(last), at(last + 1)) : at(last);
  return {low, high};
}

// Area of the circular segment cut off by a chord of length c on a circle of curvature |k|.
double segment_area(double chord, double k) {
  const double half_angle = std::asin(std::min(1.0, 0.5 * chord * std::abs(k)));
  const double theta = 2 * half_angle;
  // (θ − sin θ)/(2k²), by its series where θ is small.
  if (theta < 1e-3) return chord * chord * chord * std::abs(k) / 12.0;
  return (theta - std::sin(theta)) / (2 * k * k);
}

}  // namespace

CircleField fitted_circle_field(const Point2* q, const double* at, int count, double d,
                                const CircleField& start, double max_curvature) {
  // Parameters p: the gradient's angle, the slope and the curvature. The residuals at_i − model
  // and their derivatives: with ρ² = ξ² + η² and R = √((1 + kξ)² + (kη)²), the field is
  // d + s·f with f = (R − 1)/k = (2ξ + kρ²)/(1 + R) (no cancellation at small k).
  using Vector = Eigen::Matrix<double, 4, 1>;
  using Jacobian = Eigen::Matrix<double, 4, 3>;
  const auto evaluate = [&](const Eigen::Vector3d& p, Vector& r, Jacobian* jacobian) {
    const double nx = std::cos(p[0]), ny = std::sin(p[0]), s = p[1], k = p[2];
    r.setZero();
    if (jacobian) jacobian->setZero();
    for (int i = 0; i < count; ++i) {
      const double xi = nx * q[i].x + ny * q[i].y, eta = -ny * q[i].x + nx * q[i].y;
      const double rho2 = xi * xi + eta * eta;
      const double root = std::sqrt((1 + k * xi) * (1 + k * xi) + (k * eta) * (k * eta));
      const double f = (2 * xi + k * rho2) / (1 + root);
      r[i] = at[i] - d - s * f;
      if (!jacobian) continue;
      const double root_k = (xi + k * rho2) / root;  // ∂R/∂k
      const double f_k =
          (rho2 * (1 + root) - (2 * xi + k * rho2) * root_k) / ((1 + root) * (1 + root));
      (*jacobian)(i, 0) = -s * eta / root;  // turning n moves ξ by η and η by −ξ
      (*jacobian)(i, 1) = -f;
      (*jacobian)(i, 2) = -s * f_k;
    }
    return r.squaredNorm();
  };
  const double scale = std::max(start.slope, 1e-12);
  const Eigen::Vector3d tolerance(1e-10, 1e-10 * scale, 1e-10 * max_curvature);
  Eigen::Vector3d p(std::atan2(start.ny, start.nx), start.slope, start.curvature);
  Vector r, trial_r;
  Jacobian jacobian;
  double error = evaluate(p, r, &jacobian);
  double damping = 1e-6;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Eigen::Matrix3d normal = jacobian.transpose() * jacobian;
    const Eigen::Vector3d gradient = -jacobian.transpose() * r;
    bool moved = false, converged = false;
    for (int attempt = 0; attempt < 12 && !moved; ++attempt) {
      Eigen::Matrix3d damped = normal;
      damped.diagonal() += damping * (normal.diagonal().array() + 1e-300).matrix();
      Eigen::Vector3d trial = p + damped.ldlt().solve(gradient);
      trial[1] = std::max(trial[1], 1e-3 * scale);
      trial[2] = std::clamp(trial[2], -max_curvature, max_curvature);
      converged = ((trial - p).array().abs() <= tolerance.array()).all();
      const double trial_error = evaluate(trial, trial_r, nullptr);
      if (trial_error <= error) {
        p = trial;
        error = evaluate(p, r, &jacobian);
        damping = std::max(damping * 0.1, 1e-12);
        moved = true;
      } else {
        damping *= 10;
      }
    }
    if (!moved || converged) break;
  }
  return {std::cos(p[0]), std::sin(p[0]), p[1], p[2]};
}

LevelSet level_set_at(double nx, double ny, double slope, double curvature, double d, double b,
                      double max_curvature) {
  const double level = (b - d) / slope;
  // The level sets are concentric: the radius 1/k grows by `level`.
  const double grown = 1.0 + curvature * level;
  const double k = grown > 0.0 ? curvature / grown : std::copysign(max_curvature, curvature);
  return {nx, ny, level, std::clamp(k, -max_curvature, max_curvature)};
}

int append_level_chords(const LevelSet& set, double hx, double hy, std::vector<HalfPlane>& sides) {
  const double tx = -set.ny, ty = set.nx;
  const auto [low, high] = span_in_cell(set, hx, hy);
  const double half_span = 0.5 * (high - low);
  const double side = 2 * std::sqrt(hx * hy);
  const double sagitta = 0.5 * std::abs(set.curvature) * half_span * half_span;
  const int chords = sagitta < 0.05 * side ? 1 : sagitta < 0.5 * side ? 2 : 4;
  const double sign = set.curvature >= 0 ? 1.0 : -1.0;  // the convex side below or above
  for (int i = 0; i < chords; ++i) {
    const double e0 = low + (high - low) * i / chords, e1 = low + (high - low) * (i + 1) / chords;
    const double f0 = arc(set, e0), f1 = arc(set, e1);
    const double s = (f1 - f0) / (e1 - e0);
    const double length = std::hypot(e1 - e0, f1 - f0);
    // Moved towards the arc (up for a convex side below) by the segment's area over its length.
    const double lift = sign * segment_area(length, set.curvature) / length;
    const double c = f0 - s * e0 + lift * std::sqrt(1 + s * s);
    // ξ − s·η ≤ c below the chord; ≥ on the other side.
    sides.push_back({sign * (set.nx - s * tx), sign * (set.ny - s * ty), sign * c});
  }
  return chords;
}

}  // namespace shapeproc::fit
