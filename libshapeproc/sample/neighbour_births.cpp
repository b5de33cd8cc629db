#include "libshapeproc/sample/neighbour_births.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/sample/ball_offset.hpp"

namespace shapeproc::sample {

std::unique_ptr<const NeighbourBirths> NeighbourBirths::make(const model::ShapeProcessModel& model,
                                                             double reach) {
  const model::NeighbourOffsets& offsets = model.neighbour_offsets;
  if (offsets.empty() || offsets.radii.empty() || !(reach > 0)) return nullptr;
  auto births = std::unique_ptr<NeighbourBirths>(new NeighbourBirths());
  births->by_shape_ = !model.shapes.empty();
  births->dimension_ = model.dimension;
  const std::size_t kinds = births->by_shape_ ? model.shapes.size() : model.categories.size();
  births->from_.resize(kinds);
  const double largest = *std::max_element(offsets.radii.begin(), offsets.radii.end());
  for (const model::NeighbourOffset& o : offsets.offsets) {
    if (o.offset.norm() + largest > reach) continue;  // beyond the grid's neighbours
    Entry e;
    e.to_category =
        births->by_shape_ ? model.shapes[static_cast<std::size_t>(o.to)].category : o.to;
    e.to_shape = births->by_shape_ ? o.to : 0;
    e.offset = o.offset;
    e.probability = o.weight;
    births->from_[static_cast<std::size_t>(o.from)].push_back(e);
  }
  for (auto& list : births->from_) {
    if (list.empty()) return nullptr;
    double total = 0.0;
    for (const Entry& e : list) total += e.probability;
    std::vector<double> cumulative;
    double running = 0.0;
    for (Entry& e : list) {
      e.probability /= total;
      running += e.probability;
      cumulative.push_back(running);
    }
    births->cumulative_.push_back(std::move(cumulative));
  }
  for (double r : offsets.radii) {
    births->radii_.push_back(r);
    births->ball_measure_.push_back(geometry::ball_measure(r, model.dimension));
  }
  return births;
}

Element NeighbourBirths::propose(const Element& anchor, core::Random& random) const {
  const std::size_t from = static_cast<std::size_t>(kind(anchor));
  const std::vector<double>& cumulative = cumulative_[from];
  const std::size_t pick =
      std::min(cumulative.size() - 1,
               static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(),
                                                         random.uniform() * cumulative.back()) -
                                        cumulative.begin()));
  const Entry& entry = from_[from][pick];
  const double radius = radii_[random.index(radii_.size())];
  const Vec3 jitter = offset_in_ball(random, radius, dimension_);
  Element xi;
  xi.category = entry.to_category;
  xi.shape = entry.to_shape;
  xi.position = anchor.position + entry.offset + jitter;
  return xi;
}

double NeighbourBirths::density(const Element& xi, const Configuration& configuration,
                                int skip) const {
  const int anchors = configuration.size() - (skip >= 0 ? 1 : 0);
  if (anchors <= 0) return 0.0;
  const int to = kind(xi);
  double total = 0.0;
  configuration.for_each_near(xi.position, [&](int slot, const Element& anchor) {
    if (slot == skip) return;
    for (const Entry& e : from_[static_cast<std::size_t>(kind(anchor))]) {
      if ((by_shape_ ? e.to_shape : e.to_category) != to) continue;
      const double squared =
          geometry::minimum_image(xi.position - anchor.position - e.offset, configuration.period())
              .squaredNorm();
      for (std::size_t r = 0; r < radii_.size(); ++r)
        if (squared <= radii_[r] * radii_[r])
          total += e.probability / (static_cast<double>(radii_.size()) * ball_measure_[r]);
    }
  });
  return total / anchors;
}

}  // namespace shapeproc::sample
