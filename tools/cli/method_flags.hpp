// The options of the comparison methods of `synthesize` (--method ma-em, davison, ijiri): what
// each flag means, its checks, and how the flags become the library's options.
#pragma once

#include <string>

#include "libshapeproc/methods/davison2018/region_growing.hpp"
#include "libshapeproc/methods/ijiri2008/seed_and_grow.hpp"
#include "libshapeproc/methods/ma2011/neighbourhood_em.hpp"

namespace CLI {
class App;
}

namespace shapeproc::cli {

// The neighbourhood EM's options (--method ma-em), and the shared --neighbourhood, --k, --alpha
// and --orientation-field.
struct EmFlags {
  double rings = methods::EmOptions{}.rings;
  int k = methods::EmOptions{}.k;
  double alpha = methods::EmOptions{}.alpha;
  double lambda = methods::EmOptions{}.lambda;
  std::string samples = "auto";
  std::string initialisation = "patch-copy";
  std::string search = "k-coherence";
  std::string reconstruction = "rigid";
  std::string orientation;
  bool physics = false;
  bool copy_patches = false;  // --copy-patches: patch copy without its diversity
  int physics_steps = methods::kPhysicsSubSteps;

  // The options both neighbourhood methods (ma-em, davison) take.
  void add_shared_to(CLI::App& command);

  void add_to(CLI::App& command);

  void add_orientation_to(CLI::App& command);

  methods::EmOptions options(const geometry::Domain& domain, long long iterations) const;
};

// Region growing's options (--method davison), and --overlap, which ijiri takes too.
struct GrowthFlags {
  double ratio = methods::GrowthOptions{}.ratio;
  double patch_radius = methods::GrowthOptions{}.patch_radius;
  double bounding_radius = 0.0;
  bool no_optimise = false;
  bool no_calibrate = false;
  std::string overlap;
  // A second exemplar grown beside the first (Davison's palette), with its own parameters.
  std::string palette;
  double palette_rings = 0.0, palette_bounding_radius = -1.0;

  // --overlap, which ijiri takes too.
  void add_overlap_to(CLI::App& command);

  void add_to(CLI::App& command);

  methods::GrowthOptions options(const EmFlags& shared) const;
};

// Seed-and-grow's options (--method ijiri).
struct IjiriFlags {
  std::string rotation = "none", flips, seeds, priority, weights = "1,1,100", show;
  bool no_relax = false;

  void add_to(CLI::App& command);

  methods::SeedGrowthOptions options(const geometry::Scene& exemplar,
                                     const std::string& orientation, const std::string& overlap,
                                     const geometry::Domain& domain) const;
};

// Draws the exemplar's connectivity to an .svg (--show-connectivity).
void show_connectivity(const methods::SeedGrowthExemplar& exemplar, const std::string& file);

}  // namespace shapeproc::cli
