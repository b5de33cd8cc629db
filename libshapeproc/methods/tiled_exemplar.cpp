#include "libshapeproc/methods/tiled_exemplar.hpp"

#include <string>
#include <utility>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"

namespace shapeproc::methods {

TiledExemplar::TiledExemplar(geometry::Scene exemplar, geometry::Domain domain)
    : exemplar_(std::move(exemplar)), domain_(std::move(domain)) {
  core::check(!exemplar_.elements.empty(), "tile", "the exemplar has no elements");
  core::check(domain_.dimension() == exemplar_.dimension, "tile",
              "the domain is " + std::to_string(domain_.dimension()) + "D but the exemplar " +
                  std::to_string(exemplar_.dimension) + "D");
}

synthesis::SynthesisResult TiledExemplar::synthesize(core::Random&,
                                                     const synthesis::ChainControl& control) const {
  synthesis::SynthesisResult out;
  out.scene = exemplar_;
  out.scene.notes.clear();
  out.scene.window = domain_.box();
  out.scene.elements = geometry::tile_over(exemplar_, domain_.box());
  if (control.progress) control.progress(1, 1);
  out.record.method = method();
  out.record.set_domain(domain_);
  out.record.iterations = "0";
  out.counters = {{"tiles' elements", std::to_string(out.scene.elements.size())}};
  return out;
}

}  // namespace shapeproc::methods
