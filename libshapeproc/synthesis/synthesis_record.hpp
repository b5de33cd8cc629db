// What made a synthesised output, recorded inside it by io (SVG <metadata>, OBJ/PLY comments, a
// CSV's JSON sidecar) and read back by `stats --boundary auto`, the report and the comparison:
// the method, the seed and chain, the domain, the method's options and the steps it took.
// Every synthesis method fills the same record.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::synthesis {

struct SynthesisRecord {
  std::string method;                  // "shape-process", "neighbourhood-em", "region-growing"
  std::string command;                 // the subcommand that ran it ("sample", "synthesize")
  std::vector<std::string> arguments;  // the whole command line
  std::uint64_t seed = 1;              // the run's seed
  int chain = 1, chains = 1;           // this output's chain (1-based) of how many
  std::uint64_t chain_seed = 1;        // the seed this chain drew from (chain 1: the run's seed)
  geometry::Boundary boundary = geometry::Boundary::torus;
  std::vector<double> size;                 // the domain box's sizes (W,H or W,H,D)
  std::string domain_file, intensity_file;  // where the mask and the intensity map came from
  // Files the run read (("exemplar", path), ("model", path)) and the method's options as text,
  // in a fixed order ("shift_probability" = "0.333..."; nested ones as "fit.quantiles").
  std::vector<std::pair<std::string, std::string>> inputs, options;
  // The step budget as asked for: a count or "stationary" (the automatic rule).
  std::string iterations = "stationary";
  long long steps = 0;     // steps the chain made
  bool stationary = true;  // false when an automatic stopping rule gave up
  double seconds = 0.0;    // wall time; kept in memory only, so the same seed writes the same bytes

  // Takes the domain's boundary and box sizes.
  void set_domain(const geometry::Domain& domain);
  // Takes into this record (a command's: command, arguments, inputs, its own options) what one
  // run of a method recorded: the method, the domain (its files where this record has none), the
  // method's options after the command's, the step budget, the steps and whether it stopped at
  // stationarity.
  void take_run(const SynthesisRecord& run);
  // The value of option or input `key`, empty when absent.
  std::string option(const std::string& key) const;
  std::string input(const std::string& key) const;
  // "shapeproc synthesize, shape-process, seed 1, 38474 steps (until stationary), torus": one line
  // for reports.
  std::string summary() const;
};

}  // namespace shapeproc::synthesis
