#include "libshapeproc/fit/cluster_centres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::fit {

namespace {

using geometry::Vec3;

constexpr int kRadii = 60;   // r grid of K̂
constexpr int kScales = 80;  // σ grid of the contrast
constexpr int kLloydRounds = 20;

struct KEstimate {
  std::vector<double> r, k;
};

// K̂(r) on r = r_max i / kRadii, with the translation edge correction |W| / |W ∩ (W + d)| on an
// open window (none on a torus, where distances are the minimum image's).
KEstimate ripley_k(const std::vector<Vec3>& points, const geometry::Box3& window, bool periodic,
                   double r_max) {
  const Vec3 size = window.sizes();
  const double area = size.x() * size.y();
  const double n = static_cast<double>(points.size());
  std::vector<double> weight_at(kRadii + 1, 0.0);
  const Vec3 period = periodic ? Vec3(size.x(), size.y(), 0) : Vec3::Zero();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const Vec3 d = geometry::minimum_image(points[j] - points[i], period);
      const double distance = d.head<2>().norm();
      if (distance > r_max) continue;
      const double overlap =
          periodic ? area : (size.x() - std::abs(d.x())) * (size.y() - std::abs(d.y()));
      if (!(overlap > 0)) continue;
      const int bin = static_cast<int>(std::ceil(distance / r_max * kRadii));
      weight_at[static_cast<std::size_t>(std::clamp(bin, 0, kRadii))] += 2.0 * area / overlap;
    }
  KEstimate out;
  double cumulative = 0.0;
  for (int i = 1; i <= kRadii; ++i) {
    cumulative += weight_at[static_cast<std::size_t>(i)] + (i == 1 ? weight_at[0] : 0.0);
    out.r.push_back(r_max * i / kRadii);
    out.k.push_back(area * cumulative / (n * (n - 1)));
  }
  return out;
}

// Minimum contrast (Diggle 1983): for each σ of a grid from r_max / 200 to r_max / 2, the 1/κ
// that fits K̂ − πr² best in least squares weighted by 1/r² (K̂'s variance grows as r²), and the
// σ of the least residual.
void fit_thomas(const KEstimate& estimate, double r_max, ClusterFit& fit) {
  double best = std::numeric_limits<double>::infinity();
  for (int s = 0; s < kScales; ++s) {
    const double sigma = r_max / 200.0 * std::pow(100.0, static_cast<double>(s) / (kScales - 1));
    double df = 0.0, ff = 0.0, dd = 0.0;
    for (std::size_t i = 0; i < estimate.r.size(); ++i) {
      const double r = estimate.r[i];
      const double excess = estimate.k[i] - core::kPi * r * r;
      const double f = 1.0 - std::exp(-r * r / (4 * sigma * sigma));
      df += excess * f / (r * r);
      ff += f * f / (r * r);
      dd += excess * excess / (r * r);
    }
    const double a = std::max(0.0, df / ff);
    const double residual = dd - 2 * a * df + a * a * ff;
    if (residual < best && a > 0) {
      best = residual;
      fit.sigma = sigma;
      fit.kappa = 1.0 / a;
    }
  }
}

// κ|W| centres: seeded at the point with the most unclaimed points within 2σ (their mean), those
// points then claimed; then Lloyd's rounds: each point to its nearest centre, each centre to its
// points' mean (a centre left without points is dropped).
std::vector<Vec3> cluster_centres(const std::vector<Vec3>& points, int wanted, double sigma,
                                  const Vec3& period) {
  const auto distance = [&](const Vec3& a, const Vec3& b) {
    return geometry::minimum_image(b - a, period).head<2>().norm();
  };
  std::vector<char> claimed(points.size(), 0);
  std::vector<Vec3> centres;
  while (static_cast<int>(centres.size()) < wanted) {
    int best = -1, best_count = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (claimed[i]) continue;
      int count = 0;
      for (std::size_t j = 0; j < points.size(); ++j)
        count += !claimed[j] && distance(points[i], points[j]) < 2 * sigma;
      if (count > best_count) best = static_cast<int>(i), best_count = count;
    }
    if (best < 0) break;
    Vec3 sum = Vec3::Zero();
    for (std::size_t j = 0; j < points.size(); ++j)
      if (!claimed[j] && distance(points[static_cast<std::size_t>(best)], points[j]) < 2 * sigma) {
        sum += geometry::minimum_image(points[j] - points[static_cast<std::size_t>(best)], period);
        claimed[j] = 1;
      }
    centres.push_back(points[static_cast<std::size_t>(best)] + sum / best_count);
  }
  for (int round = 0; round < kLloydRounds; ++round) {
    std::vector<Vec3> sum(centres.size(), Vec3::Zero());
    std::vector<int> count(centres.size(), 0);
    for (const Vec3& p : points) {
      std::size_t nearest = 0;
      for (std::size_t c = 1; c < centres.size(); ++c)
        if (distance(p, centres[c]) < distance(p, centres[nearest])) nearest = c;
      sum[nearest] += geometry::minimum_image(p - centres[nearest], period);
      ++count[nearest];
    }
    std::vector<Vec3> moved;
    for (std::size_t c = 0; c < centres.size(); ++c)
      if (count[c] > 0) moved.push_back(centres[c] + sum[c] / count[c]);
    centres = std::move(moved);
  }
  return centres;
}

}  // namespace

ClusterFit find_clusters(const geometry::Scene& exemplar, bool periodic,
                         const ClusterOptions& options) {
  ClusterFit fit;
  std::vector<Vec3> points;
  for (const geometry::Element& e : exemplar.elements) points.push_back(e.position);
  const Vec3 size = exemplar.window.sizes();
  const double area = size.x() * size.y();
  const double n = static_cast<double>(points.size());
  if (exemplar.dimension != 2 || points.size() < 2 * options.min_cluster_size || !(area > 0)) {
    fit.note = "clusters: not looked for (a 2D point pattern of at least " +
               core::format_general(2 * options.min_cluster_size, 3) + " points is needed)";
    return fit;
  }
  const double r_max = 0.25 * std::min(size.x(), size.y());
  const KEstimate estimate = ripley_k(points, exemplar.window, periodic, r_max);
  fit_thomas(estimate, r_max, fit);
  const double expected_size = fit.kappa > 0 ? n / (fit.kappa * area) : 0.0;
  if (fit.sigma > 0) {
    const double r = std::min(2 * fit.sigma, r_max);
    const std::size_t i = std::min(estimate.r.size() - 1,
                                   static_cast<std::size_t>(std::ceil(r / r_max * kRadii)) - 1);
    const double excess = estimate.k[i] - core::kPi * estimate.r[i] * estimate.r[i];
    fit.z = excess / (std::sqrt(2 * core::kPi * area) * estimate.r[i] / n);
  }
  std::ostringstream note;
  note << "clusters: Thomas fit to Ripley's K, sigma " << core::format_general(fit.sigma, 3) << ", "
       << core::format_general(expected_size, 3) << " points per cluster, excess of K at "
       << "2 sigma " << core::format_general(fit.z, 3) << " standard errors";
  fit.clustered =
      fit.z >= options.min_z && expected_size >= options.min_cluster_size && 2 * fit.sigma < r_max;
  if (fit.clustered) {
    const int wanted = std::max(1, static_cast<int>(std::lround(fit.kappa * area)));
    const Vec3 period = periodic ? Vec3(size.x(), size.y(), 0) : Vec3::Zero();
    fit.centres = cluster_centres(points, wanted, fit.sigma, period);
    const geometry::Domain window(exemplar.window, 2,
                                  periodic ? geometry::Boundary::torus : geometry::Boundary::open);
    for (Vec3& c : fit.centres) c = window.wrap(c);
    note << ": clustered, " << fit.centres.size() << " centres placed as a hidden category";
  } else {
    note << ": not clustered";
  }
  fit.note = note.str();
  return fit;
}

}  // namespace shapeproc::fit
