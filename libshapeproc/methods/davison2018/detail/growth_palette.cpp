#include "libshapeproc/methods/davison2018/detail/growth_palette.hpp"

#include <algorithm>
#include <string>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::methods {

namespace {

// Index offsets of one part in the palette.
struct Offsets {
  int element = 0, sample = 0, shape = 0, category = 0, shape_class = 0, attribute = 0;
};

int largest(const std::vector<int>& values) {
  int m = -1;
  for (const int v : values) m = std::max(m, v);
  return m;
}

geometry::Neighbourhood shifted(geometry::Neighbourhood hood, const Offsets& at) {
  for (geometry::Neighbour& n : hood) {
    n.element += at.sample;
    n.attribute += at.attribute;
  }
  return hood;
}

void append_scene(geometry::Scene& to, const geometry::Scene& part, const Offsets& at,
                  int part_number) {
  for (geometry::Category category : part.categories) {
    const bool taken =
        std::any_of(to.categories.begin(), to.categories.end(),
                    [&](const geometry::Category& c) { return c.name == category.name; });
    if (taken) category.name += " #" + std::to_string(part_number + 1);
    to.categories.push_back(std::move(category));
  }
  to.shapes.insert(to.shapes.end(), part.shapes.begin(), part.shapes.end());
  for (geometry::Element e : part.elements) {
    e.shape += at.shape;
    e.category += at.category;
    to.elements.push_back(e);
  }
}

void append_exemplar(EmExemplar& to, const EmExemplar& part, const Offsets& at) {
  to.templates.insert(to.templates.end(), part.templates.begin(), part.templates.end());
  ElementSamples& s = to.samples;
  const ElementSamples& from = part.samples;
  s.positions.insert(s.positions.end(), from.positions.begin(), from.positions.end());
  for (const int e : from.element) s.element.push_back(e + at.element);
  s.sample_id.insert(s.sample_id.end(), from.sample_id.begin(), from.sample_id.end());
  s.key.insert(s.key.end(), from.key.begin(), from.key.end());
  for (std::size_t i = 1; i < from.first.size(); ++i) s.first.push_back(from.first[i] + at.sample);
  for (std::size_t e = 0; e < part.category.size(); ++e) {
    to.category.push_back(part.category[e] + at.category);
    to.shape_class.push_back(part.shape_class[e] < 0 ? -1 : part.shape_class[e] + at.shape_class);
    to.attribute.push_back(part.attribute[e] + at.attribute);
  }
  for (const int a : part.sample_attribute) to.sample_attribute.push_back(a + at.attribute);
  for (std::size_t i = 0; i < part.near.size(); ++i) {
    to.near.push_back(shifted(part.near[i], at));
    to.wide.emplace_back(shifted(part.wide[i].neighbours(), at), part.radius, part.scene.dimension);
  }
  for (std::size_t key = 0; key < part.by_key.size(); ++key) {
    if (to.by_key.size() <= key) to.by_key.resize(key + 1);
    for (const int sample : part.by_key[key]) to.by_key[key].push_back(sample + at.sample);
  }
}

void append_growth(GrowthExemplar& to, const GrowthExemplar& part, const Offsets& at,
                   int part_number) {
  for (const std::vector<int>& set : part.sets.sets) {
    to.sets.sets.emplace_back();
    for (const int m : set) to.sets.sets.back().push_back(m + at.sample);
  }
  to.radius.insert(to.radius.end(), part.radius.begin(), part.radius.end());
  to.reach.insert(to.reach.end(), part.reach.begin(), part.reach.end());
  to.spacing.insert(to.spacing.end(), part.spacing.begin(), part.spacing.end());
  to.part.insert(to.part.end(), part.reach.size(), part_number);
  to.part_density.push_back(part.em.density);
  to.free.insert(to.free.end(), part.free.begin(), part.free.end());
  to.proxy2.insert(to.proxy2.end(), part.proxy2.begin(), part.proxy2.end());
  to.proxy3.insert(to.proxy3.end(), part.proxy3.begin(), part.proxy3.end());
  to.shape_radius.insert(to.shape_radius.end(), part.shape_radius.begin(), part.shape_radius.end());
}

}  // namespace

GrowthExemplar merge_palette(std::vector<GrowthExemplar> parts) {
  if (parts.empty()) throw core::ArgumentError("palette", "no exemplar to join");
  GrowthExemplar out = std::move(parts.front());
  for (std::size_t p = 1; p < parts.size(); ++p) {
    const GrowthExemplar& part = parts[p];
    if (part.em.scene.dimension != out.em.scene.dimension)
      throw core::ArgumentError("palette", "the exemplars are not of one dimension");
    if (part.exact != out.exact)
      throw core::ArgumentError("palette", "the exemplars do not share one overlap test");
    Offsets at;
    at.element = static_cast<int>(out.em.scene.elements.size());
    at.sample = static_cast<int>(out.em.samples.size());
    at.shape = static_cast<int>(out.em.scene.shapes.size());
    at.category = static_cast<int>(out.em.scene.categories.size());
    at.shape_class = largest(out.em.shape_class) + 1;
    at.attribute = largest(out.em.attribute) + 1;
    append_scene(out.em.scene, part.em.scene, at, static_cast<int>(p));
    append_exemplar(out.em, part.em, at);
    append_growth(out, part, at, static_cast<int>(p));
  }
  return out;
}

}  // namespace shapeproc::methods
