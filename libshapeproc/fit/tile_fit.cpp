#include "libshapeproc/fit/tile_fit.hpp"

#include <utility>

#include "libshapeproc/geometry/tile_repeat.hpp"

namespace shapeproc::fit {

namespace {

// The repeat and its fit, before refinement.
void choose_repeats(const geometry::Scene& tile,
                    const std::function<FitResult(const geometry::Scene&, int)>& fit_scene,
                    TileFit& out) {
  out.repeats = geometry::tile_repeats(tile.elements.size());
  out.exemplar = geometry::repeat_tile(tile, out.repeats);
  out.result = fit_scene(out.exemplar, out.repeats);
  if (out.repeats <= 1) return;
  const int needed =
      geometry::repeats_to_hold(tile, out.result.model.interaction_range(), out.repeats);
  const auto times = [](int k) { return std::to_string(k) + " x " + std::to_string(k); };
  if (needed > kMaxTileRepeats) {
    out.notes.push_back("the interactions reach further than half the side of the tile repeated " +
                        times(out.repeats) + "; holding them would take " + times(needed) +
                        " repeats, more than the " + std::to_string(kMaxTileRepeats) +
                        " this fit allows, so far pairs are seen at nearer images");
  } else if (needed > out.repeats) {
    out.notes.push_back("fitted on the tile repeated " + times(needed) +
                        ": the interactions fitted on " + times(out.repeats) +
                        " reach further than half its side");
    out.repeats = needed;
    out.exemplar = geometry::repeat_tile(tile, needed);
    out.result = fit_scene(out.exemplar, needed);
  }
}

}  // namespace

TileFit fit_tile(const geometry::Scene& tile,
                 const std::function<FitResult(const geometry::Scene&, int)>& fit_scene,
                 const std::function<FitResult(const geometry::Scene&, int, FitResult)>& refine) {
  TileFit out;
  choose_repeats(tile, fit_scene, out);
  if (refine) out.result = refine(out.exemplar, out.repeats, std::move(out.result));
  return out;
}

}  // namespace shapeproc::fit
