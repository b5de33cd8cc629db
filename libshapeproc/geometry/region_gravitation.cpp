#include "libshapeproc/geometry/region_gravitation.hpp"

#include <array>
#include <cmath>

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
    case 1: set({0.0}, {2.0}); break;
    case 2: set({-0.5773502691896257, 0.5773502691896257}, {1.0, 1.0}); break;
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

}  // namespace

void MassBoundary2::add_edge(const Vec2& a, const Vec2& b, const Vec2& outward_normal) {
  start.push_back(a);
  end.push_back(b);
  normal.push_back(outward_normal);
  const double length = (b - a).norm();
  const double c = a.dot(outward_normal);  // x·n is constant along the edge
  area += 0.5 * c * length;                // ∫_A 1 = ½ ∮ x·n
  centroid += (c * length / 3.0) * (0.5 * (a + b));  // ∫_A x = ⅓ ∮ x (x·n)
}

void MassBoundary2::finish() {
  if (start.empty()) {
    point = true;
    area = 1.0;
    radius = 0.0;
    return;
  }
  if (area > 0) centroid /= area;
  radius = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    radius = std::max({radius, (start[i] - centroid).norm(), (end[i] - centroid).norm()});
  }
}

Vec2 gravitation_force(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset) {
  const Vec2 between = b.centroid + offset - a.centroid;
  const double distance = between.norm();
  if (a.point && b.point) return distance > 0 ? Vec2(between / (distance * distance * distance)) : Vec2::Zero();
  if (distance > 20.0 * (a.radius + b.radius) && distance > 0) {
    return (a.area * b.area / (distance * distance * distance)) * between;
  }
  if (a.point || b.point) {
    // A unit point mass p and a region R: ∫_R (y − p)/|y − p|^3 dy = −∮_∂R n / |y − p| ds.
    const bool a_is_point = a.point;
    const MassBoundary2& region = a_is_point ? b : a;
    const Vec2 p = a_is_point ? Vec2(a.centroid - offset) : Vec2(b.centroid + offset);
    Vec2 towards_region = Vec2::Zero();
    for (std::size_t j = 0; j < region.start.size(); ++j) {
      const Vec2 edge = region.end[j] - region.start[j];
      const double length = edge.norm();
      if (length == 0) continue;
      const Vec2 u = edge / length;
      const Vec2 d = region.start[j] - p;
      const double h = std::abs(d.dot(Vec2(-u.y(), u.x())));
      const double s = -d.dot(u);
      if (h == 0.0 && s >= 0 && s <= length) continue;  // p on the edge: principal value
      towards_region -= region.normal[j] * inverse_distance_integral(s, std::max(h, 1e-300), length);
    }
    return a_is_point ? towards_region : Vec2(-towards_region);
  }
  Vec2 total = Vec2::Zero();
  const std::size_t nb = b.start.size();
  std::vector<Vec2> b_start(nb), b_unit(nb);
  std::vector<double> b_length(nb);
  for (std::size_t j = 0; j < nb; ++j) {
    b_start[j] = b.start[j] + offset;
    const Vec2 edge = b.end[j] - b.start[j];
    b_length[j] = edge.norm();
    b_unit[j] = b_length[j] > 0 ? Vec2(edge / b_length[j]) : Vec2::Zero();
  }
  for (std::size_t i = 0; i < a.start.size(); ++i) {
    const Vec2 ai = a.start[i], edge_i = a.end[i] - a.start[i];
    const double length_i = edge_i.norm();
    if (length_i == 0) continue;
    const Vec2 mid_i = ai + 0.5 * edge_i;
    double integral = 0.0;  // Σ_j ∫_edge_i h_j L_j ds_x
    for (std::size_t j = 0; j < nb; ++j) {
      if (b_length[j] == 0) continue;
      const Vec2 mid_j = b_start[j] + 0.5 * b_length[j] * b_unit[j];
      const double ratio = (mid_j - mid_i).norm() / (length_i + b_length[j]);
      const GaussRule& g = ratio > 4.0 ? kRules[0] : ratio > 1.5 ? kRules[1] : ratio > 0.7 ? kRules[2] : kRules[3];
      double sum = 0.0;
      for (int k = 0; k < g.n; ++k) {
        sum += g.w[k] * edge_term(ai + g.x[k] * edge_i, b_start[j], b_unit[j], b_length[j], b.normal[j]);
      }
      integral += sum;
    }
    total += (integral * length_i) * a.normal[i];
  }
  return total;
}

}  // namespace shapeproc::geometry
