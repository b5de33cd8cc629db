// What `synthesize` runs once its flags are parsed and checked, shared by `compare`, which runs
// every method in turn with its defaults.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "tools/cli/flags.hpp"
#include "tools/cli/method_flags.hpp"

namespace shapeproc::cli {

struct SynthesizeArguments {
  std::string input, output, model, method = "shape-process", start_from = "ma-em", start = "auto";
  FitFlags fit;
  ReaderFlags reader;
  SampleFlags sample;
  EmFlags em;
  GrowthFlags growth;
  IjiriFlags ijiri;
  // The names of each method's own options (set as they are added to the command), so that a
  // method refuses the others'.
  std::vector<std::string> fit_only, shared, em_only, growth_only, orientation, ijiri_only,
      growth_overlap;
};

// Fits (shape-process, hybrid) and synthesises as `args` say, writes the outputs and prints what
// it did. `arguments`: the command line, for the records. Throws core::UsageError and
// core::InputError for what it refuses.
int run_synthesize(SynthesizeArguments& args, const std::vector<std::string>& arguments,
                   std::ostream& out);

}  // namespace shapeproc::cli
