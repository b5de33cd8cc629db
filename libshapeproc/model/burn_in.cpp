#include "libshapeproc/model/burn_in.hpp"

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::model {

std::optional<BurnIn> parse_burn_in(std::string_view name) {
  for (BurnIn b : {BurnIn::plain, BurnIn::compressing, BurnIn::crystal})
    if (name == burn_in_name(b)) return b;
  if (name == "none") return BurnIn::plain;
  return std::nullopt;
}

BurnIn output_burn_in(const ShapeProcessModel& model) {
  return model.fit && model.fit->likelihood ? model.fit->likelihood->burn_in_kind : BurnIn::plain;
}

}  // namespace shapeproc::model
