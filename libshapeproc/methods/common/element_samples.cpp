#include "libshapeproc/methods/common/element_samples.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "libshapeproc/core/check.hpp"

namespace shapeproc::methods {

namespace {

// The points' centroid and principal axes (columns, by increasing spread) with their variances.
struct PrincipalAxes {
  Vec3 centre = Vec3::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Vec3 variances = Vec3::Zero();
};

PrincipalAxes principal_axes(const std::vector<Vec3>& points, int dimension) {
  PrincipalAxes out;
  if (points.empty()) return out;
  for (const Vec3& p : points) out.centre += p;
  out.centre /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - out.centre) * (p - out.centre).transpose();
  covariance /= static_cast<double>(points.size());
  if (dimension == 2) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance.topLeftCorner<2, 2>());
    out.axes.setIdentity();
    out.axes.topLeftCorner<2, 2>() = solver.eigenvectors();
    out.variances = Vec3(0.0, solver.eigenvalues()[0], solver.eigenvalues()[1]);
    // Columns by increasing spread, the z axis (no spread) first.
    Eigen::Matrix3d sorted;
    sorted << Vec3::UnitZ(), out.axes.col(0), out.axes.col(1);
    out.axes = sorted;
  } else {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    out.axes = solver.eigenvectors();
    out.variances = solver.eigenvalues();
  }
  return out;
}

// The principal axis with a fixed sign: its first clearly non-zero coordinate positive, so that
// identical shapes number their samples alike.
Vec3 signed_axis(Vec3 axis) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(axis[k]) > 1e-9) {
      if (axis[k] < 0) axis = -axis;
      break;
    }
  }
  return axis;
}

}  // namespace

double elongation(const std::vector<Vec3>& points, int dimension) {
  const PrincipalAxes pa = principal_axes(points, dimension);
  const double largest = pa.variances[2];
  const double smallest = dimension == 2 ? pa.variances[1] : pa.variances[0];
  if (largest <= 0.0) return 1.0;
  if (smallest <= largest * 1e-18) return 1e9;
  return std::sqrt(largest / smallest);
}

int automatic_sample_count(double elongation) {
  if (elongation < 2.0) return 1;
  return static_cast<int>(std::min(8.0, std::round(elongation) + 1.0));
}

namespace {

// Points every `step` along a segment, its start included and its end not.
void densify(const Vec3& a, const Vec3& b, double step, std::vector<Vec3>& out) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
  for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * (static_cast<double>(i) / n));
}

}  // namespace

std::vector<Vec3> proxy_points(const geometry::Shape& shape, int dimension,
                               const geometry::ProxyOptions& options) {
  std::vector<Vec3> points;
  if (geometry::dimension(shape) == 0) return {Vec3::Zero()};
  const double step =
      std::max(geometry::bounding_box(shape).diagonal().norm(), 1e-12) / kOutlinePointsPerDiagonal;
  if (dimension == 2) {
    const geometry::Proxy2 proxy = geometry::make_proxy2(shape, options);
    for (const auto& line : proxy.polylines) {
      const std::size_t n = line.points.size();
      const std::size_t segments = line.closed ? n : n - 1;
      auto at = [&](std::size_t i) {
        const geometry::Vec2& p = line.points[i % n];
        return Vec3(p.x(), p.y(), 0.0);
      };
      for (std::size_t i = 0; i < segments; ++i) densify(at(i), at(i + 1), step, points);
      if (!line.closed && n > 0) points.push_back(at(n - 1));
    }
  } else {
    const geometry::Proxy3 proxy = geometry::make_proxy3(shape, options);
    points = proxy.vertices;
    // Each triangle's edges, so that long faces are sampled too.
    for (const auto& t : proxy.triangles)
      for (int k = 0; k < 3; ++k)
        densify(proxy.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])],
                proxy.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])],
                step, points);
  }
  if (points.empty()) points.push_back(Vec3::Zero());
  return points;
}

SampleTemplate sample_template(const std::vector<Vec3>& points, int dimension, int count) {
  core::check(count >= 1 && count <= kMaxSamplesPerElement, "element samples",
              "the samples per element must be 1 to " + std::to_string(kMaxSamplesPerElement));
  SampleTemplate out;
  if (count == 1 || points.size() < 2) {
    out.offsets.assign(static_cast<std::size_t>(count), Vec3::Zero());
    return out;
  }
  const PrincipalAxes pa = principal_axes(points, dimension);
  const Vec3 axis = signed_axis(pa.axes.col(2));
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Vec3& p : points) {
    const double t = (p - pa.centre).dot(axis);
    low = std::min(low, t);
    high = std::max(high, t);
  }
  // Stations at the middles of `count` equal stretches of the axis, each snapped to the nearest
  // proxy point (first found on ties).
  for (int k = 0; k < count; ++k) {
    const double t = low + (high - low) * (k + 0.5) / count;
    const Vec3 station = pa.centre + t * axis;
    const Vec3* nearest = &points.front();
    for (const Vec3& p : points)
      if ((p - station).squaredNorm() < (*nearest - station).squaredNorm()) nearest = &p;
    out.offsets.push_back(*nearest);
  }
  return out;
}

std::vector<SampleTemplate> sample_templates(const geometry::Scene& scene,
                                             const SampleOptions& options) {
  // Each shape's proxy points and elongation; one automatic count per category, from the median
  // elongation of its elements, so that a category's elements share their sample ids.
  std::vector<std::vector<Vec3>> points(scene.shapes.size());
  std::vector<double> stretch(scene.shapes.size(), 1.0);
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    points[s] = proxy_points(scene.shapes[s], scene.dimension, options.proxy);
    if (geometry::dimension(scene.shapes[s]) != 0)
      stretch[s] = elongation(points[s], scene.dimension);
  }
  std::vector<std::vector<double>> by_category(scene.categories.size());
  std::vector<int> shape_category(scene.shapes.size(), -1);
  for (const geometry::Element& e : scene.elements) {
    by_category[static_cast<std::size_t>(e.category)].push_back(
        stretch[static_cast<std::size_t>(e.shape)]);
    if (shape_category[static_cast<std::size_t>(e.shape)] < 0)
      shape_category[static_cast<std::size_t>(e.shape)] = e.category;
  }
  std::vector<int> count(scene.categories.size(), 1);
  for (std::size_t c = 0; c < by_category.size(); ++c) {
    std::vector<double>& v = by_category[c];
    if (options.per_element > 0) {
      count[c] = options.per_element;
    } else if (!v.empty()) {
      std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
      count[c] = automatic_sample_count(v[v.size() / 2]);
    }
  }
  std::vector<SampleTemplate> out;
  out.reserve(scene.shapes.size());
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    const int category = shape_category[s];
    const int n = category < 0 ? 1 : count[static_cast<std::size_t>(category)];
    out.push_back(sample_template(points[s], scene.dimension, n));
  }
  return out;
}

ElementSamples place_samples(const geometry::Scene& scene,
                             const std::vector<SampleTemplate>& templates) {
  ElementSamples out;
  out.first.reserve(scene.elements.size() + 1);
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const geometry::Element& element = scene.elements[e];
    const SampleTemplate& t = templates[static_cast<std::size_t>(element.shape)];
    const int count = static_cast<int>(t.offsets.size());
    out.first.push_back(static_cast<int>(out.positions.size()));
    for (int k = 0; k < count; ++k) {
      out.positions.push_back(element.position + t.offsets[static_cast<std::size_t>(k)]);
      out.element.push_back(static_cast<int>(e));
      out.sample_id.push_back(k);
      out.key.push_back(sample_key(count, k));
    }
  }
  out.first.push_back(static_cast<int>(out.positions.size()));
  return out;
}

}  // namespace shapeproc::methods
