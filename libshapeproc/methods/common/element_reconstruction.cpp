#include "libshapeproc/methods/common/element_reconstruction.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::methods {

const char* to_string(Reconstruction reconstruction) {
  switch (reconstruction) {
    case Reconstruction::rigid:
      return "rigid";
    case Reconstruction::similarity:
      return "similarity";
    case Reconstruction::tps:
      return "tps";
    case Reconstruction::tps_approx:
      return "tps-approx";
  }
  return "?";
}

Reconstruction parse_reconstruction(const std::string& text) {
  for (Reconstruction r : {Reconstruction::rigid, Reconstruction::similarity, Reconstruction::tps,
                           Reconstruction::tps_approx})
    if (text == to_string(r)) return r;
  throw core::ArgumentError(
      "element reconstruction",
      "reconstruction: expected rigid, similarity, tps or tps-approx, got '" + text + "'");
}

Similarity fit_similarity(const std::vector<Vec3>& from, const std::vector<Vec3>& to, int dimension,
                          bool scaling) {
  Similarity s;
  const auto n = static_cast<Eigen::Index>(from.size());
  if (n == 1) {
    s.translation = to[0] - from[0];
    return s;
  }
  Eigen::MatrixXd a(dimension, n), b(dimension, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a.col(i) = from[static_cast<std::size_t>(i)].head(dimension);
    b.col(i) = to[static_cast<std::size_t>(i)].head(dimension);
  }
  const Eigen::MatrixXd t = Eigen::umeyama(a, b, scaling);
  s.linear.topLeftCorner(dimension, dimension) = t.topLeftCorner(dimension, dimension);
  s.translation.head(dimension) = t.topRightCorner(dimension, 1);
  return s;
}

double ThinPlateSpline::kernel(double r) const {
  if (dimension_ == 3) return r;
  return r > 0.0 ? r * r * std::log(r) : 0.0;
}

ThinPlateSpline::ThinPlateSpline(const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                                 int dimension, bool interpolating)
    : dimension_(dimension), base_(fit_similarity(from, to, dimension)), centres_(from) {
  const auto n = static_cast<Eigen::Index>(from.size());
  const Eigen::Index m = n + dimension + 1;
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(m, m);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 3);
  double magnitude = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const double k =
          kernel((from[static_cast<std::size_t>(i)] - from[static_cast<std::size_t>(j)]).norm());
      system(i, j) = k;
      magnitude += std::abs(k);
    }
    system(i, n) = system(n, i) = 1.0;
    for (int a = 0; a < dimension; ++a)
      system(i, n + 1 + a) = system(n + 1 + a, i) = from[static_cast<std::size_t>(i)][a];
    rhs.row(i) =
        (to[static_cast<std::size_t>(i)] - base_(from[static_cast<std::size_t>(i)])).transpose();
  }
  if (!interpolating && n > 1) {
    const double smoothing = magnitude / static_cast<double>(n * (n - 1));
    for (Eigen::Index i = 0; i < n; ++i) system(i, i) += smoothing;
  }
  // Least norm where the samples leave the affine part open (collinear samples): the similarity
  // then carries the missing directions.
  weights_ = system.completeOrthogonalDecomposition().solve(rhs);
}

Vec3 ThinPlateSpline::operator()(const Vec3& x) const {
  const auto n = static_cast<Eigen::Index>(centres_.size());
  Vec3 y = base_(x) + weights_.row(n).transpose();
  for (int a = 0; a < dimension_; ++a) y += x[a] * weights_.row(n + 1 + a).transpose();
  for (Eigen::Index i = 0; i < n; ++i)
    y += kernel((x - centres_[static_cast<std::size_t>(i)]).norm()) * weights_.row(i).transpose();
  if (dimension_ == 2) y.z() = 0.0;
  return y;
}

geometry::Shape map_shape(const geometry::Shape& shape,
                          const std::function<Vec3(const Vec3&)>& map) {
  geometry::Shape out = shape;
  auto map2 = [&](geometry::Vec2& p) {
    const Vec3 q = map(Vec3(p.x(), p.y(), 0.0));
    p = geometry::Vec2(q.x(), q.y());
  };
  if (auto* planar = std::get_if<geometry::PlanarShape>(&out.geometry)) {
    for (geometry::Drawable2& d : planar->parts)
      for (geometry::Path2& path : d.paths)
        for (geometry::Segment2& s : path.segments) {
          map2(s.start);
          map2(s.control1);
          map2(s.control2);
          map2(s.end);
        }
  } else if (auto* mesh = std::get_if<geometry::MeshShape>(&out.geometry)) {
    for (Vec3& v : mesh->mesh.vertices) v = map(v);
  }
  return out;
}

namespace {

// Element e's samples, unwrapped around its first one.
std::vector<Vec3> unwrapped_samples(const OutputSamples& output, std::size_t e,
                                    const geometry::Domain& domain) {
  const ElementSamples& samples = output.samples;
  const int first = samples.first[e], count = samples.count_of(static_cast<int>(e));
  const Vec3 anchor = samples.positions[static_cast<std::size_t>(first)];
  std::vector<Vec3> to;
  for (int k = 0; k < count; ++k)
    to.push_back(anchor + domain.minimum_image(
                              samples.positions[static_cast<std::size_t>(first + k)] - anchor));
  return to;
}

const SampleTemplate& template_of(const EmExemplar& exemplar, const OutputSamples& output,
                                  std::size_t e) {
  const geometry::Element& source =
      exemplar.scene.elements[static_cast<std::size_t>(output.source[e])];
  return exemplar.templates[static_cast<std::size_t>(source.shape)];
}

// The points that carry a shape: its path points (2D) or vertices (3D).
std::vector<Vec3> shape_points(const geometry::Shape& shape) {
  std::vector<Vec3> points;
  map_shape(shape, [&points](const Vec3& p) {
    points.push_back(p);
    return p;
  });
  return points;
}

// The spread of points along their principal axes: the covariance's eigenvalues, ascending.
Eigen::VectorXd principal_spreads(const std::vector<Vec3>& points, int dimension) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(dimension, dimension);
  for (const Vec3& p : points) {
    const Eigen::VectorXd d = (p - mean).head(dimension);
    covariance += d * d.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(covariance).eigenvalues();
}

// Whether `mapped` (the points of `from`, mapped) keeps their size and proportions within
// kMaxSplineDistortion: the product of the principal spreads (area², volume²) and the ratio of
// the largest to the smallest. A flat shape (a line) is judged by its largest spread alone.
bool within_distortion_bound(const Eigen::VectorXd& from, const std::vector<Vec3>& mapped,
                             int dimension) {
  const Eigen::VectorXd to = principal_spreads(mapped, dimension);
  const double limit = kMaxSplineDistortion * kMaxSplineDistortion;  // spreads are squares
  const auto within = [limit](double ratio) { return ratio <= limit && ratio * limit >= 1.0; };
  const double flat = 1e-12 * from.maxCoeff();
  if (!(to.minCoeff() > flat) || !(from.minCoeff() > flat))
    return from.minCoeff() <= flat && within(to.maxCoeff() / from.maxCoeff());
  return within(to.prod() / from.prod()) &&
         within((to.maxCoeff() / to.minCoeff()) / (from.maxCoeff() / from.minCoeff()));
}

// The spline's map of `shape`, blended towards `rigid` by halves until within the bound (at the
// sixth halving, the rigid placement itself).
geometry::Shape bounded_spline_shape(const geometry::Shape& shape, const ThinPlateSpline& spline,
                                     const Similarity& rigid, int dimension) {
  const std::vector<Vec3> points = shape_points(shape);
  const Eigen::VectorXd spreads = principal_spreads(points, dimension);
  double share = 1.0;
  for (int halving = 0; halving < 6; ++halving, share /= 2) {
    // (An Eigen expression of temporaries must not outlive the return: the lambda returns a Vec3.)
    const auto blended = [&](const Vec3& x) -> Vec3 {
      return rigid(x) + share * (spline(x) - rigid(x));
    };
    std::vector<Vec3> mapped;
    mapped.reserve(points.size());
    for (const Vec3& p : points) mapped.push_back(blended(p));
    if (within_distortion_bound(spreads, mapped, dimension)) return map_shape(shape, blended);
  }
  return map_shape(shape, rigid);
}

}  // namespace

Similarity rigid_placement(const EmExemplar& exemplar, const OutputSamples& output, std::size_t e,
                           const geometry::Domain& domain, const OrientationField& orientation) {
  const SampleTemplate& t = template_of(exemplar, output, e);
  const std::vector<Vec3> to = unwrapped_samples(output, e, domain);
  if (to.size() > 1) return fit_similarity(t.offsets, to, exemplar.scene.dimension, false);
  Similarity s;
  const double radians = orientation.angle_at(to[0]);
  if (radians != 0.0) s.linear = Eigen::AngleAxisd(radians, Vec3::UnitZ()).toRotationMatrix();
  s.translation = to[0] - s.linear * t.offsets[0];
  return s;
}

geometry::Scene reconstruct(const EmExemplar& exemplar, const OutputSamples& output,
                            const geometry::Domain& domain, const OrientationField& orientation,
                            Reconstruction rule) {
  geometry::Scene scene;
  scene.dimension = exemplar.scene.dimension;
  scene.window = domain.box();
  scene.units = exemplar.scene.units;
  scene.categories = exemplar.scene.categories;
  scene.shapes = exemplar.scene.shapes;
  const int dim = scene.dimension;
  for (std::size_t e = 0; e < output.elements(); ++e) {
    const geometry::Element& source =
        exemplar.scene.elements[static_cast<std::size_t>(output.source[e])];
    const SampleTemplate& t = template_of(exemplar, output, e);
    const std::vector<Vec3> to = unwrapped_samples(output, e, domain);
    const geometry::Shape& shape = exemplar.scene.shapes[static_cast<std::size_t>(source.shape)];
    const auto count = static_cast<int>(to.size());
    if (count == 1 || rule == Reconstruction::rigid || rule == Reconstruction::similarity ||
        count < dim + 1) {
      const Similarity s = count == 1 || rule == Reconstruction::rigid
                               ? rigid_placement(exemplar, output, e, domain, orientation)
                               : fit_similarity(t.offsets, to, dim, true);
      if (s.linear.isIdentity(0.0)) {
        // The drawn shape itself, moved: shared with the exemplar, not copied.
        scene.elements.push_back({source.shape, source.category, domain.wrap(s.translation)});
        continue;
      }
      geometry::add_element(scene, map_shape(shape, s), source.category);
    } else {
      const ThinPlateSpline spline(t.offsets, to, dim, rule == Reconstruction::tps);
      geometry::add_element(
          scene,
          bounded_spline_shape(shape, spline,
                               rigid_placement(exemplar, output, e, domain, orientation), dim),
          source.category);
    }
    geometry::Element& added = scene.elements.back();
    added.position = domain.wrap(added.position);
  }
  return scene;
}

}  // namespace shapeproc::methods
