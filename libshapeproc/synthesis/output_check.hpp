// What an output's count says about its chain, against the exemplar's density: an output its
// own chain emptied is nothing to write, and one far short of the density is worth a warning. Both
// `synthesize` and `sample` apply it before writing; a library caller gets the same verdicts.
#pragma once

#include <vector>

#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::synthesis {

// Whether an output of `count` elements falls short of the `wanted` count its exemplar's density
// gives by more than chance: below 0.9 of it and more than three standard errors below it,
// 3 √(wanted × dispersion): Poisson's for dispersion 1; a cluster process whose clusters hold m
// elements on average varies 1 + m times as much. A small output of a loose exemplar varies by that
// much (two-kinds at 136 wanted: 120 is 1.4 standard errors short); a model that cannot fill its
// exemplar's packing from empty falls far shorter (happy-intersection: 251 of 405).
bool falls_short(double count, double wanted, double dispersion = 1.0);

struct OutputCheck {
  double wanted = 0.0;  // elements the exemplar's density gives the output's domain
  double count = 0.0;   // elements the output holds (drawn ones: hidden categories left out)
  // The chain ran to its automatic stop and ended empty where the density gives at least one
  // element: a model whose chains either fill the domain or empty it, and this one emptied.
  bool emptied = false;
  // The count is far below `wanted` (falls_short; an output with hidden cluster centres at the
  // dispersion of its clusters, 1 + elements per centre): the model does not reach its
  // exemplar's packing from empty.
  bool short_of_density = false;
  double ratio() const { return wanted > 0 ? count / wanted : 0.0; }
};

// `exemplar_density`: elements per unit measure of the exemplar (the model's fit record); a
// non-positive one checks nothing. `automatic_stop`: the chain ran until its stopping rule (no
// step count given), so that its final state is the method's verdict, not a snapshot asked for.
OutputCheck check_output(const SynthesisResult& result, double exemplar_density,
                         bool automatic_stop);

// Throws core::UsageError naming the first emptied chain, and saying nothing was written, when
// any of `results` is; the outputs are then not to be written.
void refuse_emptied(const std::vector<SynthesisResult>& results, double exemplar_density,
                    bool automatic_stop);

}  // namespace shapeproc::synthesis
