// The interface every synthesis method implements, so that one runner, one output record and one
// set of metrics serve them all. Construction does the method's precomputation once (proxies,
// the compiled interaction, tables); `synthesize` runs one chain from a generator it is given.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/synthesis/synthesis_record.hpp"

namespace shapeproc::synthesis {

// What a chain may tell its caller and ask of it while it runs.
struct ChainControl {
  // Called now and then with the steps done so far and the chain's total (0: not known in
  // advance, e.g. an automatic stopping rule). May be empty.
  std::function<void(long long done, long long total)> progress;
  // Set by another thread to stop the chain early (it then throws core::Cancelled). May be null.
  const std::atomic<bool>* cancel = nullptr;

  bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
};

// One point of a chain's trace: the state every so many steps.
struct TracePoint {
  long long step = 0;
  int elements = 0;
  double log_density = 0.0;  // the method's own score (the shape process: unnormalised log f(x))
};

struct SynthesisResult {
  geometry::Scene scene;          // the elements made, with the domain's box as window
  SynthesisRecord record;         // the method's part filled; run_chains adds chain and time
  std::vector<TracePoint> trace;  // empty unless asked for
  // Sufficient statistics t(x) observed along the chain, for methods that are exponential
  // families (the shape process: SamplerOptions::observe_every); empty otherwise.
  std::vector<std::vector<double>> observations;
  // Elements of hidden categories the method placed and left out of `scene` (a clustered
  // pattern's centres, model::CategoryParameters::hidden); 0 for the other methods.
  long long hidden_elements = 0;
  // Method-specific counters, in order, for a one-line summary ("births accepted" = "512/20000").
  std::vector<std::pair<std::string, std::string>> counters;
};

class Synthesizer {
 public:
  virtual ~Synthesizer() = default;
  // The method's name as records carry it ("shape-process").
  virtual std::string method() const = 0;
  // One chain. Must depend only on the generator's stream (same seed, same output) and must not
  // change the synthesizer, so that chains may run at once on several threads.
  virtual SynthesisResult synthesize(core::Random& random, const ChainControl& control) const = 0;
};

}  // namespace shapeproc::synthesis
