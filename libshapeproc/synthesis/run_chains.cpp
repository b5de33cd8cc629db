#include "libshapeproc/synthesis/run_chains.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/stopwatch.hpp"

namespace shapeproc::synthesis {

std::uint64_t chain_seed(std::uint64_t seed, int chain) {
  if (chain == 0) return seed;
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(chain + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

namespace {

// Sums the chains' progress into one report over all of them.
class ProgressSum {
 public:
  ProgressSum(int chains, std::function<void(long long, long long)> report)
      : done_(static_cast<std::size_t>(chains), 0), report_(std::move(report)) {}

  void update(int chain, long long done, long long total) {
    if (!report_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    done_[static_cast<std::size_t>(chain)] = done;
    long long sum = 0;
    for (long long d : done_) sum += d;
    if (total <= 0) unknown_ = true;
    report_(sum, unknown_ ? 0 : total * static_cast<long long>(done_.size()));
  }

 private:
  std::mutex mutex_;
  std::vector<long long> done_;
  bool unknown_ = false;
  std::function<void(long long, long long)> report_;
};

}  // namespace

int chains_at_once(int chains, int threads) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(chains, threads > 0 ? threads : cores));
}

std::vector<SynthesisResult> run_chains(const Synthesizer& synthesizer,
                                        const ChainOptions& options) {
  core::check(options.chains >= 1, "run_chains",
              "at least one chain is needed, got " + std::to_string(options.chains));
  core::check(options.threads >= 0, "run_chains", "the thread count must be >= 0");
  const int chains = options.chains;
  std::vector<SynthesisResult> results(static_cast<std::size_t>(chains));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(chains));
  ProgressSum progress(chains, options.progress);
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int c = next++; c < chains; c = next++) {
      const std::size_t index = static_cast<std::size_t>(c);
      ChainControl control;
      control.cancel = options.cancel;
      if (options.progress)
        control.progress = [&progress, c](long long done, long long total) {
          progress.update(c, done, total);
        };
      const std::uint64_t seed = chain_seed(options.seed, c);
      core::Random random(seed);
      const core::Stopwatch watch;
      try {
        SynthesisResult result = synthesizer.synthesize(random, control);
        SynthesisRecord record = options.record;
        record.take_run(result.record);
        record.method = synthesizer.method();
        record.seed = options.seed;
        record.chain = c + 1;
        record.chains = chains;
        record.chain_seed = seed;
        record.seconds = watch.seconds();
        result.record = std::move(record);
        results[index] = std::move(result);
      } catch (...) {
        errors[index] = std::current_exception();
      }
    }
  };
  const int thread_count = chains_at_once(chains, options.threads);
  std::vector<std::thread> pool;
  for (int t = 1; t < thread_count; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  SHAPEPROC_ASSERT(next.load() >= chains, "every chain ran");
  return results;
}

}  // namespace shapeproc::synthesis
