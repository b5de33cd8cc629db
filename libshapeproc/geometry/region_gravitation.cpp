#include "libshapeproc/geometry/region_gravitation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/gravitation.hpp"
#include "libshapeproc/geometry/segment_distance.hpp"

namespace shapeproc::geometry {

namespace {

// Gauss–Legendre nodes on [0, 1] and weights summing to 1, for 1, 2, 4 and 8 points.
struct GaussRule {
  int n;
  std::array<double, 8> x, w;
};

GaussRule rule(int n) {
  GaussRule r{n, {}, {}};
  auto set = [&](std::initializer_list<double> nodes, std::initializer_list<double> weights) {
    int k = 0;
    for (double node : nodes) r.x[k++] = node;
    k = 0;
    for (double weight : weights) r.w[k++] = weight;
  };
  switch (n) {
    case 1:
      set({0.0}, {2.0});
      break;
    case 2:
      set({-0.5773502691896257, 0.5773502691896257}, {1.0, 1.0});
      break;
    case 4:
      set({-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526},
          {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538});
      break;
    default:
      r.n = 8;
      set({-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
           0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363},
          {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
           0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763});
  }
  for (int k = 0; k < r.n; ++k) {
    r.x[k] = 0.5 * (r.x[k] + 1.0);
    r.w[k] *= 0.5;
  }
  return r;
}

const GaussRule kRules[4] = {rule(1), rule(2), rule(4), rule(8)};

// Lanes of the edge-pair loop: its sums run in this many fixed partial sums, so that the result
// does not depend on the width of the vector registers the compiler uses.
constexpr std::size_t kLanes = 4;

// Edges per cluster, and the distance (in cluster radii, beyond the edge's length) from which an
// edge sees a cluster's expansion: its error is then below about (1/4)⁴ of the cluster's share.
constexpr std::size_t kClusterEdges = 16;
constexpr double kClusterFar = 4.0;

// For the edge i of A with Gauss points x0, x1, midpoint m and length ℓ_i (in B's frame): the sum
// over B's edges j apart from it (midpoints more than ℓ_i + ℓ_j apart) of the two-point Gauss
// product rule for the mean along edge i of ∫_edge_j h_j(x)/|y − x| ds_y, where
// h_j(x) = (y − x)·n_j = n_j·start_j − n_j·x. The entries of the edges j not apart go to `near`.
// (|h_j| ≤ |y − x|, and squared distances are kept above 1e-300, so no term is infinite.) When
// `clustered`, the edges of a cluster far from edge i (every such edge is apart from it) count
// through the cluster's expansion, at both Gauss points, instead.
double apart_sum(const MassBoundary2& boundary, bool clustered, double x0x, double x0y, double x1x,
                 double x1y, double mx, double my, double length_i,
                 std::vector<std::size_t>& near) {
  using Lanes = Eigen::Array<double, kLanes, 1>;
  using Load = Eigen::Map<const Lanes>;
  using R = MassBoundary2::EdgeRule;
  const MassBoundary2::EdgeRule& b = boundary.rule;
  Lanes sum = Lanes::Zero();
  double far = 0.0;
  const Lanes tiny = Lanes::Constant(1e-300);
  for (const EdgeCluster& cluster : boundary.clusters) {
    const double cx = cluster.centre.x() - mx, cy = cluster.centre.y() - my;
    const double reach = kClusterFar * cluster.radius + length_i;
    if (clustered && cx * cx + cy * cy > reach * reach) {
      far += 0.5 * (cluster.potential(Vec2(x0x, x0y)) + cluster.potential(Vec2(x1x, x1y)));
      continue;
    }
    for (std::size_t j = cluster.begin; j < cluster.end; j += kLanes) {
      const Lanes dx = Load(b[R::mx] + j) - mx, dy = Load(b[R::my] + j) - my;
      const Lanes reach_j = Load(b[R::length] + j) + length_i;
      const auto apart = dx * dx + dy * dy > reach_j * reach_j;
      const Lanes nx = Load(b[R::nx] + j), ny = Load(b[R::ny] + j), c = Load(b[R::c] + j);
      const Lanes h0 = c - (nx * x0x + ny * x0y), h1 = c - (nx * x1x + ny * x1y);
      const Lanes y0x = Load(b[R::y0x] + j), y0y = Load(b[R::y0y] + j);
      const Lanes y1x = Load(b[R::y1x] + j), y1y = Load(b[R::y1y] + j);
      const Lanes r00 = ((y0x - x0x).square() + (y0y - x0y).square()).max(tiny).sqrt();
      const Lanes r01 = ((y1x - x0x).square() + (y1y - x0y).square()).max(tiny).sqrt();
      const Lanes r10 = ((y0x - x1x).square() + (y0y - x1y).square()).max(tiny).sqrt();
      const Lanes r11 = ((y1x - x1x).square() + (y1y - x1y).square()).max(tiny).sqrt();
      // 1/r + 1/r' as (r + r')/(r r'): two divisions instead of four.
      const Lanes term = h0 * (r00 + r01) / (r00 * r01) + h1 * (r10 + r11) / (r10 * r11);
      sum += apart.select(Load(b[R::quarter] + j) * term, 0.0);
      if (!apart.all()) {
        for (std::size_t k = 0; k < kLanes; ++k) {
          if (!apart[static_cast<Eigen::Index>(k)]) near.push_back(j + k);
        }
      }
    }
  }
  return ((sum[0] + sum[1]) + (sum[2] + sum[3])) + far;
}

// ∫_0^ℓ dt / sqrt((t − s)^2 + h^2) for h > 0, in a form stable when x is near the edge's line.
double inverse_distance_integral(double s, double h, double length) {
  const double h2 = h * h;
  const double far = length - s;
  const double r1 = std::sqrt(far * far + h2), r0 = std::sqrt(s * s + h2);
  const double numerator = far >= 0 ? far + r1 : h2 / (r1 - far);
  const double denominator = s <= 0 ? -s + r0 : h2 / (r0 + s);
  return std::log(numerator / denominator);
}

// h_j(x) ∫_edge_j ds_y / |y − x| for the edge (a, unit direction u, length ℓ, normal n).
double edge_term(const Vec2& x, const Vec2& a, const Vec2& u, double length, const Vec2& n) {
  const Vec2 d = a - x;
  const double h = d.dot(n);  // (y − x)·n_j, the same for every y on the edge
  if (h == 0.0) return 0.0;
  const double s = -d.dot(u);  // position of x's projection along the edge
  return h * inverse_distance_integral(s, std::abs(h), length);
}

using Complex = std::complex<double>;

// Gauss–Legendre nodes on [0, 1] and weights summing to 1, n points (Newton's method on P_n).
struct GaussTable {
  std::vector<double> x, w;
};

GaussTable gauss_legendre(int n) {
  GaussTable table;
  for (int i = 0; i < n; ++i) {
    double t = std::cos(core::kPi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = t;  // P_0, P_1, then up to P_n by the three-term recurrence
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (t * p1 - p0) / (t * t - 1);
      const double step = p1 / derivative;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    table.x.push_back(0.5 * (1 - t));
    table.w.push_back(1.0 / ((1 - t * t) * derivative * derivative));  // 2/((1−t²)P'²), halved
  }
  return table;
}

// α_k = C(2k, k) / 4^k up to kMomentOrder.
struct ExpansionConstants {
  std::array<double, kMomentOrder + 1> alpha{};
  GaussTable moment_rule =
      gauss_legendre(kMomentOrder / 2 + 1);  // exact for degree kMomentOrder + 1
  ExpansionConstants() {
    alpha[0] = 1.0;
    for (int k = 1; k <= kMomentOrder; ++k) alpha[k] = alpha[k - 1] * (2 * k - 1) / (2 * k);
  }
};

const ExpansionConstants& constants() {
  static const ExpansionConstants table;
  return table;
}

constexpr double kExpansionTolerance = 1e-6;

// Smallest order p with `growth(p)` s^{p+1} below the tolerance, or -1 beyond `highest`.
template <class Growth>
int expansion_order(double s, Growth&& growth, int highest = kMomentOrder) {
  double power = s;
  for (int p = 0; p <= highest; ++p) {
    power *= s;  // s^{p+2}: one order of margin for the bound's constants
    if (growth(p) * power <= kExpansionTolerance) return p;
  }
  return -1;
}

// Φ_B at x (relative to B's centroid, |x| > B's radius), truncated at total order `order`.
double expanded_potential(const MassBoundary2& b, const Complex& x, int order) {
  const ExpansionConstants& c = constants();
  std::array<Complex, kMomentOrder + 1> power;
  power[0] = 1.0;
  const Complex u = std::conj(x) / std::norm(x);
  for (int k = 1; k <= order; ++k) power[k] = power[k - 1] * u;
  // Terms (k, l) and (l, k) are conjugate: sum l ≤ k, twice when l < k.
  double sum = 0.0;
  for (int n = 0; n <= order; ++n) {
    for (int l = 0; 2 * l <= n; ++l) {
      const int k = n - l;
      const double weight = (k == l ? 1.0 : 2.0) * c.alpha[k] * c.alpha[l];
      sum +=
          weight * (b.complex_moments[moment_index(k, l)] * power[k] * std::conj(power[l])).real();
    }
  }
  return sum / std::abs(x);
}

// ∇U for U(R) = (1/|R|) Σ G_kl R^{−k} R̄^{−l}: as a complex number 2 ∂U/∂R̄
// = −(1/|R|) Σ (2l + 1) G_kl R^{−k} R̄^{−l−1}. With v = 1/R and w = v̄ the sum is
// Σ_l (2l + 1) w^{l+1} P_l(v), P_l(v) = Σ_{k ≤ order − l} G_kl v^k: each P_l from a table of
// powers of v (independent products), the sum over l by Horner's rule in w. One complex product
// per term, written out in real arithmetic.
Vec2 expanded_force(const PairExpansion& pair, const Complex& r, int order) {
  const Complex v = std::conj(r) / std::norm(r);
  const double vr = v.real(), vi = v.imag();
  std::array<double, kMomentOrder + 1> power_r, power_i;
  power_r[0] = 1.0;
  power_i[0] = 0.0;
  for (std::size_t k = 1; k <= static_cast<std::size_t>(order); ++k) {
    power_r[k] = power_r[k - 1] * vr - power_i[k - 1] * vi;
    power_i[k] = power_r[k - 1] * vi + power_i[k - 1] * vr;
  }
  double outer_r = 0.0, outer_i = 0.0;
  for (int l = order; l >= 0; --l) {
    double pr = 0.0, pi = 0.0;
    for (int k = 0; k <= order - l; ++k) {
      const Complex& g = pair.g[static_cast<std::size_t>(moment_index(k, l))];
      const std::size_t kk = static_cast<std::size_t>(k);
      pr += g.real() * power_r[kk] - g.imag() * power_i[kk];
      pi += g.real() * power_i[kk] + g.imag() * power_r[kk];
    }
    const double ar = outer_r + (2.0 * l + 1.0) * pr, ai = outer_i + (2.0 * l + 1.0) * pi;
    outer_r = ar * vr + ai * vi;  // × w = v̄
    outer_i = ai * vr - ar * vi;
  }
  const double scale = -1.0 / std::abs(r);
  return Vec2(scale * outer_r, scale * outer_i);
}

}  // namespace

void MassBoundary2::add_edge(const Vec2& a, const Vec2& b, const Vec2& outward_normal) {
  start.push_back(a);
  end.push_back(b);
  normal.push_back(outward_normal);
  const double edge_length = (b - a).norm();
  const double c = a.dot(outward_normal);                 // x·n is constant along the edge
  area += 0.5 * c * edge_length;                          // ∫_A 1 = ½ ∮ x·n
  centroid += (c * edge_length / 3.0) * (0.5 * (a + b));  // ∫_A x = ⅓ ∮ x (x·n)
  // ∫_A x x^T = ¼ ∮ x x^T (x·n), the edge integral by Simpson's rule (exact for quadratics).
  const Vec2 m = 0.5 * (a + b);
  moments +=
      (c * edge_length / 24.0) * (a * a.transpose() + 4.0 * m * m.transpose() + b * b.transpose());
}

void MassBoundary2::finish() {
  complex_moments.assign(kMomentCount, Complex(0.0, 0.0));
  if (start.empty()) {
    point = true;
    area = 1.0;
    radius = 0.0;
    complex_moments[0] = 1.0;
    return;
  }
  if (area > 0) {
    centroid /= area;
    moments -= area * centroid * centroid.transpose();  // about the centroid
  }
  radius = 0.0;
  unit.assign(start.size(), Vec2::Zero());
  length.assign(start.size(), 0.0);
  for (std::size_t i = 0; i < start.size(); ++i) {
    radius = std::max({radius, (start[i] - centroid).norm(), (end[i] - centroid).norm()});
    length[i] = (end[i] - start[i]).norm();
    if (length[i] > 0) unit[i] = (end[i] - start[i]) / length[i];
  }
  rule = EdgeRule{};
  const auto push = [&](const std::array<double, EdgeRule::kColumns>& values, int edge) {
    for (std::size_t k = 0; k < values.size(); ++k) rule.columns[k].push_back(values[k]);
    rule.edge.push_back(edge);
  };
  clusters.clear();
  std::vector<int> edges;
  for (std::size_t i = 0; i < start.size(); ++i)
    if (length[i] > 0.0) edges.push_back(static_cast<int>(i));
  for (const std::vector<int>& group : group_nearby_edges(start, end, edges, kClusterEdges)) {
    EdgeCluster cluster;
    cluster.begin = rule.edge.size();
    Box2 box;
    for (const int j : group)
      box.extend(start[static_cast<std::size_t>(j)]).extend(end[static_cast<std::size_t>(j)]);
    cluster.centre = box.center();
    for (const int j : group) {
      const auto i = static_cast<std::size_t>(j);
      const Vec2 y0 = start[i] + kRules[1].x[0] * (end[i] - start[i]),
                 y1 = start[i] + kRules[1].x[1] * (end[i] - start[i]);
      const Vec2 m = 0.5 * (start[i] + end[i]);
      push({y0.x(), y0.y(), y1.x(), y1.y(), m.x(), m.y(), normal[i].x(), normal[i].y(),
            start[i].dot(normal[i]), 0.25 * length[i], length[i]},
           j);
      cluster.add_edge(start[i], end[i], normal[i]);
    }
    // Padding: far away, no normal and no weight, so that its terms are exactly 0 and never near.
    constexpr double kAway = 1e100;
    while (rule.edge.size() % kLanes != 0)
      push({kAway, kAway, kAway, kAway, kAway, kAway, 0, 0, 0, 0, 0}, -1);
    cluster.end = rule.edge.size();
    clusters.push_back(cluster);
  }
  // M_kl = ∫ z^k z̄^l dA = 1/(2(l + 1)) ∮ n z^k z̄^{l+1} ds (complex Green's theorem with
  // dz = i n ds on the positively oriented boundary); the edge integrands are polynomials of
  // degree ≤ kMomentOrder + 1, integrated exactly.
  const ExpansionConstants& c = constants();
  std::array<Complex, kMomentOrder + 2> power, conjugate;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (length[i] == 0.0) continue;
    const Complex n(normal[i].x(), normal[i].y());
    for (std::size_t g = 0; g < c.moment_rule.x.size(); ++g) {
      const Vec2 y = start[i] + c.moment_rule.x[g] * (end[i] - start[i]) - centroid;
      const Complex z(y.x(), y.y());
      power[0] = conjugate[0] = 1.0;
      for (int k = 1; k <= kMomentOrder + 1; ++k) {
        power[k] = power[k - 1] * z;
        conjugate[k] = std::conj(power[k]);
      }
      const Complex weight = c.moment_rule.w[g] * length[i] * n;
      for (int total = 0; total <= kMomentOrder; ++total) {
        for (int l = 0; l <= total; ++l) {
          complex_moments[moment_index(total - l, l)] +=
              weight * power[total - l] * conjugate[l + 1];
        }
      }
    }
  }
  for (int total = 0; total <= kMomentOrder; ++total) {
    for (int l = 0; l <= total; ++l) complex_moments[moment_index(total - l, l)] /= 2.0 * (l + 1);
  }
}

PairExpansion pair_expansion(const MassBoundary2& a, const MassBoundary2& b) {
  // 1/|R + w| with w = ξ − y (ξ about A's centroid, y about B's): the binomial expansion of
  // w^k w̄^l in the moments of both, G_kl = α_k α_l Σ C(k, i) C(l, j) (−1)^{i+j} M^A_ij M^B_{k−i,
  // l−j}, computed as α_k α_l k! l! Σ a_ij b_{k−i, l−j} with a_ij = (−1)^{i+j} M^A_ij / (i! j!) and
  // b_ij = M^B_ij / (i! j!), so that the inner sum is one complex product per term.
  std::array<double, kMomentOrder + 1> factorial{};
  factorial[0] = 1.0;
  for (int k = 1; k <= kMomentOrder; ++k) factorial[k] = factorial[k - 1] * k;
  std::array<std::array<Complex, kMomentOrder + 1>, kMomentOrder + 1> scaled_a{}, scaled_b{};
  for (int i = 0; i <= kMomentOrder; ++i) {
    for (int j = 0; i + j <= kMomentOrder; ++j) {
      const double scale = 1.0 / (factorial[i] * factorial[j]);
      const double sign = (i + j) % 2 == 0 ? 1.0 : -1.0;
      scaled_a[i][j] = sign * scale * a.complex_moments[moment_index(i, j)];
      scaled_b[i][j] = scale * b.complex_moments[moment_index(i, j)];
    }
  }
  const ExpansionConstants& c = constants();
  PairExpansion pair;
  pair.g.assign(kMomentCount, Complex(0.0, 0.0));
  for (int total = 0; total <= kMomentOrder; ++total) {
    for (int l = 0; l <= total; ++l) {
      const int k = total - l;
      Complex sum = 0.0;
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= l; ++j) sum += scaled_a[i][j] * scaled_b[k - i][l - j];
      }
      pair.g[static_cast<std::size_t>(moment_index(k, l))] =
          c.alpha[k] * c.alpha[l] * factorial[k] * factorial[l] * sum;
    }
  }
  pair.order_bound.assign(kMomentOrder + 1, 0.0);
  for (int total = 0; total <= kMomentOrder; ++total) {
    for (int l = 0; l <= total; ++l) {
      pair.order_bound[static_cast<std::size_t>(total)] +=
          (2.0 * l + 1.0) * std::abs(pair.g[static_cast<std::size_t>(moment_index(total - l, l))]);
    }
  }
  return pair;
}

double monopole_deviation(const PairExpansion& pair, double radii, double distance) {
  const double s = radii / distance;
  const double monopole = pair.order_bound.empty() ? 0.0 : pair.order_bound[0];
  if (!(s < 0.9) || !(monopole > 0.0)) return std::numeric_limits<double>::infinity();
  // Orders 1..p from the table, by Horner in 1/|R|; beyond p, terms of order n are at most
  // (n + 1) s^n of the first (the potential's at most s^n, differentiation adds n + 1).
  double sum = 0.0;
  for (int n = kMomentOrder; n >= 1; --n)
    sum = (sum + pair.order_bound[static_cast<std::size_t>(n)]) / distance;
  const double tail = (kMomentOrder + 2.0) * std::pow(s, kMomentOrder + 1) / ((1 - s) * (1 - s));
  return sum / monopole + tail;
}

namespace {

Vec2 force(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset,
           const PairExpansion* pair, bool expansions) {
  const Vec2 between = b.centroid + offset - a.centroid;
  const double distance = between.norm();
  if (a.point && b.point)
    return distance > 0 ? Vec2(between / (distance * distance * distance)) : Vec2::Zero();
  if (expansions && pair != nullptr && distance > 0 && !a.point && !b.point) {
    const double s = (a.radius + b.radius) / distance;
    const int order = expansion_order(s, [&](int p) { return (p + 1.0) / ((1 - s) * (1 - s)); });
    if (s < 1 && order >= 0)
      return expanded_force(*pair, Complex(-between.x(), -between.y()), order);
  }
  if (distance > 5.0 * (a.radius + b.radius) && distance > 0) {
    return far_field_force<2>(a.area, a.moments, b.area, b.moments, between);
  }
  if (a.point || b.point) {
    // A unit point mass p and a region R: ∫_R (y − p)/|y − p|^3 dy = −∮_∂R n / |y − p| ds.
    const bool a_is_point = a.point;
    const MassBoundary2& region = a_is_point ? b : a;
    const Vec2 p = a_is_point ? Vec2(a.centroid - offset) : Vec2(b.centroid + offset);
    Vec2 towards_region = Vec2::Zero();
    for (std::size_t j = 0; j < region.start.size(); ++j) {
      const double length = region.length[j];
      if (length == 0) continue;
      const Vec2& u = region.unit[j];
      const Vec2 d = region.start[j] - p;
      const double h = std::abs(d.dot(Vec2(-u.y(), u.x())));
      const double s = -d.dot(u);
      if (h == 0.0 && s >= 0 && s <= length) continue;  // p on the edge: principal value
      towards_region -=
          region.normal[j] * inverse_distance_integral(s, std::max(h, 1e-300), length);
    }
    return a_is_point ? towards_region : Vec2(-towards_region);
  }
  // A's edges are taken into B's frame (moved by −offset), so B's edges are used as they are.
  Vec2 total = Vec2::Zero();
  const std::size_t nb = b.start.size();
  for (std::size_t i = 0; i < a.start.size(); ++i) {
    const double length_i = a.length[i];
    if (length_i == 0) continue;
    const Vec2 ai = a.start[i] - offset, edge_i = length_i * a.unit[i];
    double integral = 0.0;  // the mean of Φ_B along edge i
    // Edges well outside B's circle: Φ_B from B's expansion, Gauss–Legendre along the edge with
    // more points the closer the edge (Φ_B is analytic outside B).
    bool expanded = false;
    if (expansions) {
      const double gap = point_segment_distance(b.centroid, ai, ai + edge_i);
      const double s = b.radius / gap, room = (gap - b.radius) / length_i;
      const GaussRule& g = room > 6 ? kRules[1] : room > 1.5 ? kRules[2] : kRules[3];
      // Only where it is cheaper (tuned on benchmarks): (p + 1)(p + 2)/4 complex products per
      // point against one edge-pair term per edge of B.
      int affordable = -1;
      while (affordable < kMomentOrder &&
             g.n * (affordable + 2) * (affordable + 3) < 4 * static_cast<int>(nb))
        ++affordable;
      const int order = s < 0.6 && room > 0.4
                            ? expansion_order(
                                  s, [&](int) { return 1.0 / (1 - s); }, affordable)
                            : -1;
      if (order >= 0) {
        for (int k = 0; k < g.n; ++k) {
          const Vec2 x = ai + g.x[k] * edge_i - b.centroid;
          integral += g.w[k] * expanded_potential(b, Complex(x.x(), x.y()), order);
        }
        expanded = true;
      }
    }
    if (!expanded) {
      // Edge pairs apart (midpoints more than the sum of their lengths apart): two Gauss points
      // on each edge for h_j(x)/|y − x|, no logarithm; on near pairs of 12- and 16-gons the
      // median angle error of a force is 1e-5 rad (the 90th percentile, 1e-4 rad, comes from
      // the nearest edges). Nearer pairs: Gauss–Legendre along edge i of the exact integral
      // along edge j.
      const Vec2 x0 = ai + kRules[1].x[0] * edge_i, x1 = ai + kRules[1].x[1] * edge_i,
                 mid_i = ai + 0.5 * edge_i;
      thread_local std::vector<std::size_t> near;
      near.clear();
      integral = apart_sum(b, expansions, x0.x(), x0.y(), x1.x(), x1.y(), mid_i.x(), mid_i.y(),
                           length_i, near);
      for (const std::size_t e : near) {
        using R = MassBoundary2::EdgeRule;
        const double dx = b.rule[R::mx][e] - mid_i.x(), dy = b.rule[R::my][e] - mid_i.y();
        const double reach = length_i + b.rule[R::length][e];
        const std::size_t j = static_cast<std::size_t>(b.rule.edge[e]);
        const double ratio = std::sqrt(dx * dx + dy * dy) / reach;
        const GaussRule& g = ratio > 0.7 ? kRules[2] : kRules[3];
        double sum = 0.0;
        for (int k = 0; k < g.n; ++k) {
          sum += g.w[k] *
                 edge_term(ai + g.x[k] * edge_i, b.start[j], b.unit[j], b.length[j], b.normal[j]);
        }
        integral += sum;
      }
    }
    total += (integral * length_i) * a.normal[i];
  }
  return total;
}

}  // namespace

Vec2 gravitation_force(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset,
                       const PairExpansion* pair) {
  return force(a, b, offset, pair, true);
}

Vec2 gravitation_force_edges(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset) {
  return force(a, b, offset, nullptr, false);
}

namespace {

// Symmetric quadrature points of a triangle with equal weights: 1 (centroid), 3 (degree 2), or
// 3 on each of the four midpoint sub-triangles (12).
int triangle_points(const std::array<Vec3, 3>& t, int level, std::array<Vec3, 12>& out) {
  auto three = [](const Vec3& a, const Vec3& b, const Vec3& c, Vec3* p) {
    p[0] = (2.0 / 3) * a + (1.0 / 6) * (b + c);
    p[1] = (2.0 / 3) * b + (1.0 / 6) * (a + c);
    p[2] = (2.0 / 3) * c + (1.0 / 6) * (a + b);
  };
  if (level == 0) {
    out[0] = (t[0] + t[1] + t[2]) / 3.0;
    return 1;
  }
  if (level == 1) {
    three(t[0], t[1], t[2], out.data());
    return 3;
  }
  const Vec3 ab = 0.5 * (t[0] + t[1]), bc = 0.5 * (t[1] + t[2]), ca = 0.5 * (t[2] + t[0]);
  three(t[0], ab, ca, out.data());
  three(ab, t[1], bc, out.data() + 3);
  three(ca, bc, t[2], out.data() + 6);
  three(ab, bc, ca, out.data() + 9);
  return 12;
}

}  // namespace

MassSurface3 MassSurface3::from_closed_mesh(const std::vector<Vec3>& vertices,
                                            const std::vector<std::array<int, 3>>& triangles) {
  MassSurface3 s;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& t : triangles) {
    const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const Vec3 cross = (b - a).cross(c - a);
    const double twice_area = cross.norm();
    if (twice_area == 0.0) continue;
    const Vec3 n = cross / twice_area;
    const double area = 0.5 * twice_area;
    const double h = a.dot(n);  // x·n is constant on the triangle
    const Vec3 sum = a + b + c;
    s.volume += h * area / 3.0;             // ∫ 1 = ⅓ ∮ x·n
    first += (h * area / 3.0 / 4.0) * sum;  // ∫ x = ¼ ∮ x (x·n); ∫_T x = A (a+b+c)/3
    // ∫ x x^T = ⅕ ∮ x x^T (x·n); ∫_T x x^T = A/12 (Σ v v^T + S S^T)
    second += (h * area / 12.0 / 5.0) *
              (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
    s.triangles.push_back({a, b, c});
    s.normal.push_back(n);
    s.area.push_back(area);
  }
  if (s.volume < 0) {  // inward orientation: flip
    s.volume = -s.volume;
    first = -first;
    second = -second;
    for (auto& t : s.triangles) std::swap(t[1], t[2]);
    for (auto& n : s.normal) n = -n;
  }
  if (s.volume > 0) {
    s.centroid = first / s.volume;
    s.moments = second - s.volume * s.centroid * s.centroid.transpose();
  }
  for (const auto& t : s.triangles) {
    for (const Vec3& v : t) s.radius = std::max(s.radius, (v - s.centroid).norm());
    s.centre.push_back((t[0] + t[1] + t[2]) / 3.0);
    s.size.push_back(std::max({(t[0] - t[1]).norm(), (t[1] - t[2]).norm(), (t[2] - t[0]).norm()}));
    std::array<Vec3, 12> points;
    triangle_points(t, 1, points);
    s.points3.push_back({points[0], points[1], points[2]});
    triangle_points(t, 2, points);
    s.points12.push_back(points);
  }
  return s;
}

Vec3 gravitation_force(const MassSurface3& a, const MassSurface3& b, const Vec3& offset) {
  const Vec3 between = b.centroid + offset - a.centroid;
  const double distance = between.norm();
  if (distance > 5.0 * (a.radius + b.radius) && distance > 0) {
    return far_field_force<3>(a.volume, a.moments, b.volume, b.moments, between);
  }
  Vec3 total = Vec3::Zero();
  for (std::size_t i = 0; i < a.triangles.size(); ++i) {
    const Vec3 ci = a.centre[i] - offset;  // in b's frame: b's triangles stay where they are
    const double size_i = a.size[i];
    double integral = 0.0;
    for (std::size_t j = 0; j < b.triangles.size(); ++j) {
      const Vec3 r = b.centre[j] - ci;
      const double length = r.norm();
      const double reach = size_i + b.size[j];
      if (length > 2.0 * reach) {  // far apart for their sizes: one point each, the centres
        integral += r.dot(b.normal[j]) / length * b.area[j];
        continue;
      }
      // (y − x)·n_B is y·n_B − x·n_B: the second term once per point of A.
      const Vec3& n = b.normal[j];
      const auto mean = [&](const auto& pa, const auto& pb) {
        double sum = 0.0;
        for (const Vec3& p : pa) {
          const Vec3 x = p - offset;
          const double xn = x.dot(n);
          for (const Vec3& y : pb) {
            const double l = (y - x).norm();
            if (l > 0) sum += (y.dot(n) - xn) / l;
          }
        }
        return sum / static_cast<double>(pa.size() * pb.size());
      };
      integral += (length > 0.5 * reach ? mean(a.points3[i], b.points3[j])
                                        : mean(a.points12[i], b.points12[j])) *
                  b.area[j];
    }
    total += (0.5 * integral * a.area[i]) * a.normal[i];
  }
  return total;
}

}  // namespace shapeproc::geometry
