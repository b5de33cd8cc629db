// Independent chains of any synthesis method on a pool of threads, with derived seeds, one
// progress callback over all chains, and cancellation.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::synthesis {

// The seed of chain `chain` (0-based) of a run seeded `seed`: chain 0 keeps the seed, the others
// get SplitMix64 of (seed, chain), well separated for neighbouring seeds and chains.
std::uint64_t chain_seed(std::uint64_t seed, int chain);

struct ChainOptions {
  int chains = 1;
  int threads = 0;  // 0: one per core (never more than the chains)
  std::uint64_t seed = 1;
  // The caller's part of every chain's record (command, arguments, inputs); the synthesizer's part
  // and the chain's own fields are filled in.
  SynthesisRecord record;
  // Called with the steps done over all chains and their total (0 when a chain's length is not
  // known in advance), from any thread but never at once. May be empty.
  std::function<void(long long done, long long total)> progress;
  const std::atomic<bool>* cancel = nullptr;  // set it to stop every chain (run_chains then throws)
};

// Runs the chains; results in chain order. A chain that throws makes run_chains rethrow its
// exception once every thread has stopped (the first chain's error in chain order).
// Chains that run at the same time: `threads` (0: one per core), at most `chains`, at least 1.
int chains_at_once(int chains, int threads);

std::vector<SynthesisResult> run_chains(const Synthesizer& synthesizer,
                                        const ChainOptions& options);

}  // namespace shapeproc::synthesis
