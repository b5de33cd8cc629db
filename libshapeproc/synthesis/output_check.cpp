#include "libshapeproc/synthesis/output_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::synthesis {

bool falls_short(double count, double wanted, double dispersion) {
  return wanted > 0 && count < 0.9 * wanted &&
         wanted - count > 3.0 * std::sqrt(wanted * std::max(1.0, dispersion));
}

OutputCheck check_output(const SynthesisResult& result, double exemplar_density,
                         bool automatic_stop) {
  OutputCheck check;
  check.count = static_cast<double>(result.scene.elements.size());
  if (!(exemplar_density > 0)) return check;
  check.wanted = exemplar_density * result.scene.window_measure();
  check.emptied = automatic_stop && check.count == 0 && check.wanted >= 1.0;
  const double dispersion = result.hidden_elements > 0
                                ? 1.0 + check.count / static_cast<double>(result.hidden_elements)
                                : 1.0;
  check.short_of_density = falls_short(check.count, check.wanted, dispersion);
  return check;
}

void refuse_emptied(const std::vector<SynthesisResult>& results, double exemplar_density,
                    bool automatic_stop) {
  for (const SynthesisResult& result : results) {
    const OutputCheck check = check_output(result, exemplar_density, automatic_stop);
    if (check.emptied)
      throw core::UsageError("chain " + std::to_string(result.record.chain) +
                             " ended empty where the exemplar's density gives " +
                             core::format_general(check.wanted, 4) +
                             " elements: the model's chains do not hold its exemplar's elements "
                             "from empty; nothing written");
  }
}

}  // namespace shapeproc::synthesis
