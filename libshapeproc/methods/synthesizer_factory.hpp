// Every synthesis method behind one call: the shape process's sampler, the neighbourhood EM of
// Ma et al. 2011, the region growing of Davison et al. 2018, the seed-and-grow of Ijiri et al.
// 2008, the hybrid (one of those three, then the shape-process sampler) and the tile baseline
// (the exemplar repeated). `make_synthesizer` does each method's precomputation on the exemplar
// and returns it ready for synthesis::run_chains; `describe_synthesizer` says, a line each, what
// it learnt (what `shapeproc synthesize` prints before it runs).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/methods/davison2018/region_growing.hpp"
#include "libshapeproc/methods/ijiri2008/seed_and_grow.hpp"
#include "libshapeproc/methods/ma2011/neighbourhood_em.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::methods {

enum class Method { shape_process, ma_em, davison, ijiri, hybrid, tile };

// The names the command line and the records use: shape-process, ma-em, davison, ijiri, hybrid,
// tile.
std::string method_name(Method method);
std::optional<Method> method_from_name(std::string_view name);

// Each method's options; a method reads only its own (the hybrid: its start's and `sampler`).
struct MethodOptions {
  EmOptions em;          // ma-em
  GrowthOptions growth;  // davison
  std::vector<GrowthSource>
      palette;                     // davison: exemplars grown beside the first (Davison's palette)
  SeedGrowthOptions ijiri;         // ijiri
  sample::SamplerOptions sampler;  // shape-process and hybrid
  Method start_from = Method::ma_em;  // hybrid: the method whose output the sampler starts from
};

// The method, ready to run on `domain`. `exemplar` (read with `boundary`: a seamless tile is a
// torus) is what the neighbourhood methods and the tile copy; `model` (the shape process fitted
// to it) is what the shape process and the hybrid sample, and may be null for the others.
// Throws core::ArgumentError for what the method cannot do (a model missing where one is needed,
// seed-and-grow or a hybrid from it on a 3D exemplar, a palette of another dimension).
std::unique_ptr<synthesis::Synthesizer> make_synthesizer(Method method,
                                                         const geometry::Scene& exemplar,
                                                         geometry::Boundary boundary,
                                                         const geometry::Domain& domain,
                                                         const MethodOptions& options,
                                                         const model::ShapeProcessModel* model);

// What `synthesizer` (made by make_synthesizer from `exemplar`) learnt from it, a line each: the
// exemplar's elements, samples and neighbourhood radius in its units. Empty for the shape process
// (its model says it) and the hybrid.
std::vector<std::string> describe_synthesizer(const synthesis::Synthesizer& synthesizer,
                                              const geometry::Scene& exemplar,
                                              const MethodOptions& options);

}  // namespace shapeproc::methods
