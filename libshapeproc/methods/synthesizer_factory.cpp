#include "libshapeproc/methods/synthesizer_factory.hpp"

#include <array>
#include <utility>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/methods/hybrid_synthesis.hpp"
#include "libshapeproc/methods/tiled_exemplar.hpp"

namespace shapeproc::methods {

namespace {

constexpr std::array<std::pair<Method, std::string_view>, 6> kNames = {{
    {Method::shape_process, "shape-process"},
    {Method::ma_em, "ma-em"},
    {Method::davison, "davison"},
    {Method::ijiri, "ijiri"},
    {Method::hybrid, "hybrid"},
    {Method::tile, "tile"},
}};

void require_2d(const geometry::Scene& exemplar, const std::string& what) {
  if (exemplar.dimension != 2)
    throw core::ArgumentError("make_synthesizer", what + " grows 2D exemplars only");
}

// The neighbourhood methods, which the hybrid may start from too.
std::unique_ptr<synthesis::Synthesizer> make_neighbourhood_method(Method method,
                                                                  const geometry::Scene& exemplar,
                                                                  geometry::Boundary boundary,
                                                                  const geometry::Domain& domain,
                                                                  const MethodOptions& options) {
  switch (method) {
    case Method::ma_em:
      return std::make_unique<NeighbourhoodEm>(exemplar, boundary, domain, options.em);
    case Method::davison: {
      std::vector<GrowthSource> palette;
      palette.reserve(1 + options.palette.size());
      palette.push_back({exemplar, boundary});
      for (const GrowthSource& source : options.palette) {
        if (source.scene.dimension != exemplar.dimension)
          throw core::ArgumentError(
              "make_synthesizer",
              "a palette exemplar is " + std::to_string(source.scene.dimension) +
                  "D but the exemplar is " + std::to_string(exemplar.dimension) + "D");
        palette.push_back(source);
      }
      return std::make_unique<RegionGrowing>(palette, domain, options.growth);
    }
    case Method::ijiri:
      require_2d(exemplar, "seed-and-grow");
      return std::make_unique<SeedAndGrow>(exemplar, boundary, domain, options.ijiri);
    default:
      throw core::ArgumentError(
          "make_synthesizer",
          "a hybrid starts from ma-em, davison or ijiri, not " + method_name(method));
  }
}

const model::ShapeProcessModel& require_model(const model::ShapeProcessModel* model,
                                              Method method) {
  if (!model)
    throw core::ArgumentError("make_synthesizer", method_name(method) + " needs a fitted model");
  return *model;
}

}  // namespace

std::string method_name(Method method) {
  for (const auto& [m, name] : kNames)
    if (m == method) return std::string(name);
  return "unknown";
}

std::optional<Method> method_from_name(std::string_view name) {
  for (const auto& [m, known] : kNames)
    if (known == name) return m;
  return std::nullopt;
}

std::unique_ptr<synthesis::Synthesizer> make_synthesizer(Method method,
                                                         const geometry::Scene& exemplar,
                                                         geometry::Boundary boundary,
                                                         const geometry::Domain& domain,
                                                         const MethodOptions& options,
                                                         const model::ShapeProcessModel* model) {
  switch (method) {
    case Method::shape_process:
      return std::make_unique<sample::ShapeProcessSampler>(require_model(model, method), domain,
                                                           options.sampler);
    case Method::tile:
      return std::make_unique<TiledExemplar>(exemplar, domain);
    case Method::hybrid:
      return std::make_unique<HybridSynthesis>(
          make_neighbourhood_method(options.start_from, exemplar, boundary, domain, options),
          require_model(model, method), domain, options.sampler);
    default:
      return make_neighbourhood_method(method, exemplar, boundary, domain, options);
  }
}

std::vector<std::string> describe_synthesizer(const synthesis::Synthesizer& synthesizer,
                                              const geometry::Scene& exemplar,
                                              const MethodOptions& options) {
  const std::string units = ' ' + exemplar.units;
  const std::string count = std::to_string(exemplar.elements.size()) + " exemplar elements";
  if (const auto* em = dynamic_cast<const NeighbourhoodEm*>(&synthesizer))
    return {"neighbourhood EM: " + count + ", " + std::to_string(em->exemplar().samples.size()) +
            " samples, radius " + core::format_number(em->exemplar().radius) + units};
  if (const auto* ijiri = dynamic_cast<const SeedAndGrow*>(&synthesizer))
    return {"seed-and-grow: " + count + ", " + std::to_string(ijiri->exemplar().references.size()) +
            " with closed rings, mean edge " +
            core::format_number(ijiri->exemplar().connectivity.mean_edge) + units};
  if (const auto* growth = dynamic_cast<const RegionGrowing*>(&synthesizer)) {
    // A line per exemplar of the palette, at its first sample.
    std::vector<std::string> lines;
    const GrowthExemplar& grown = growth->exemplar();
    for (std::size_t s = 0, part = 0; s < grown.part.size(); ++s) {
      if (static_cast<std::size_t>(grown.part[s]) != part) continue;
      const geometry::Scene& scene = part == 0 ? exemplar : options.palette[part - 1].scene;
      lines.push_back((part == 0 ? "region growing: " : "palette: ") +
                      std::to_string(scene.elements.size()) +
                      " exemplar elements, neighbourhood radius " +
                      core::format_number(grown.reach[s]) + ' ' + scene.units);
      ++part;
    }
    return lines;
  }
  if (dynamic_cast<const TiledExemplar*>(&synthesizer))
    return {"tile: the exemplar repeated over the output (the baseline: a copy, no novelty)"};
  return {};
}

}  // namespace shapeproc::methods
