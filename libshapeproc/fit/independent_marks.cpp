#include "libshapeproc/fit/independent_marks.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace shapeproc::fit {

namespace {

// The new indices of an old category: the marks for `pooled`, one index for the others.
std::vector<std::vector<int>> new_indices(int old_count, int pooled, int marks) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(old_count));
  int next = marks;
  for (int c = 0; c < old_count; ++c) {
    if (c == pooled) {
      for (int m = 0; m < marks; ++m) out[static_cast<std::size_t>(c)].push_back(m);
    } else {
      out[static_cast<std::size_t>(c)].push_back(next++);
    }
  }
  return out;
}

}  // namespace

geometry::Scene pool_categories(const geometry::Scene& exemplar, const std::string& name) {
  geometry::Scene pooled = exemplar;
  std::string joined = name;
  if (joined.empty())
    for (const geometry::Category& c : exemplar.categories)
      joined += (joined.empty() ? "" : "+") + c.name;
  pooled.categories = {{joined}};
  for (geometry::Element& e : pooled.elements) e.category = 0;
  return pooled;
}

void split_into_marks(model::ShapeProcessModel& model, int pooled, const geometry::Scene& marked) {
  const int old_count = static_cast<int>(model.categories.size());
  if (pooled < 0 || pooled >= old_count)
    throw std::invalid_argument("split_into_marks: no category " + std::to_string(pooled));
  if (!model.shapes.empty())
    throw std::invalid_argument("split_into_marks: the model has shapes, not points");
  // A category anchored to the pooled one would have several bases: not a point pattern's fit.
  for (const model::CategoryParameters& c : model.categories)
    if (c.anchor == pooled)
      throw std::invalid_argument("split_into_marks: a category is anchored to the pooled one");
  const int marks = static_cast<int>(marked.categories.size());
  const std::vector<std::size_t> counts = geometry::category_counts(marked);
  const double total = static_cast<double>(marked.elements.size());
  const std::vector<std::vector<int>> to = new_indices(old_count, pooled, marks);
  const auto share = [&](int m) {
    return static_cast<double>(counts[static_cast<std::size_t>(m)]) / total;
  };

  std::vector<model::CategoryParameters> categories(
      static_cast<std::size_t>(marks + old_count - 1));
  for (int c = 0; c < old_count; ++c) {
    const model::CategoryParameters& old = model.categories[static_cast<std::size_t>(c)];
    for (int n : to[static_cast<std::size_t>(c)]) {
      model::CategoryParameters category = old;
      if (c == pooled) {
        category.name = marked.categories[static_cast<std::size_t>(n)].name;
        category.beta = old.beta * share(n);
        category.beta_standard_error = old.beta_standard_error * share(n);
      }
      if (old.anchor >= 0) category.anchor = to[static_cast<std::size_t>(old.anchor)].front();
      categories[static_cast<std::size_t>(n)] = std::move(category);
    }
  }

  std::vector<model::PairInteraction> interactions;
  for (const model::PairInteraction& pair : model.interactions)
    for (int a : to[static_cast<std::size_t>(pair.first)])
      for (int b : to[static_cast<std::size_t>(pair.second)]) {
        if (pair.first == pair.second && b < a) continue;
        model::PairInteraction split = pair;
        split.first = std::min(a, b);
        split.second = std::max(a, b);
        if (pair.first == pooled || pair.second == pooled)
          split.choice =
              (pair.choice.empty() ? "" : pair.choice + "; ") +
              "the pooled categories' interaction, the same for each (independent marks)";
        interactions.push_back(std::move(split));
      }

  // Births near neighbours: a pooled kind's offsets for every mark, the target's weighted by its
  // share (the offsets steer proposals only).
  model::NeighbourOffsets offsets = model.neighbour_offsets;
  offsets.offsets.clear();
  for (const model::NeighbourOffset& o : model.neighbour_offsets.offsets)
    for (int from : to[static_cast<std::size_t>(o.from)])
      for (int target : to[static_cast<std::size_t>(o.to)]) {
        model::NeighbourOffset split = o;
        split.from = from;
        split.to = target;
        if (o.to == pooled) split.weight *= share(target);
        if (split.weight > 0) offsets.offsets.push_back(split);
      }

  std::sort(interactions.begin(), interactions.end(),
            [](const model::PairInteraction& x, const model::PairInteraction& y) {
              return std::pair(x.first, x.second) < std::pair(y.first, y.second);
            });
  model.categories = std::move(categories);
  model.interactions = std::move(interactions);
  model.neighbour_offsets = std::move(offsets);
}

}  // namespace shapeproc::fit
