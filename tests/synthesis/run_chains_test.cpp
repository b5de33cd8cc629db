#include "libshapeproc/synthesis/run_chains.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <set>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::synthesis {
namespace {

// A method that places `steps` random points and reports progress every 10 steps; chain
// `failing` (its chain seed) throws.
class RandomPoints : public Synthesizer {
 public:
  explicit RandomPoints(long long steps, std::uint64_t failing_seed = 0)
      : steps_(steps), failing_seed_(failing_seed) {}
  std::string method() const override { return "random-points"; }
  SynthesisResult synthesize(core::Random& random, const ChainControl& control) const override {
    SynthesisResult result;
    const double first = random.uniform();
    if (failing_seed_ != 0 && seed_of(first) == failing_seed_)
      throw core::UsageError("chain failed");
    geometry::Element e;
    e.position = geometry::Vec3(first, 0, 0);
    result.scene.elements.push_back(e);
    for (long long step = 1; step <= steps_; ++step) {
      e.position = geometry::Vec3(random.uniform(), random.uniform(), 0);
      result.scene.elements.push_back(e);
      if (step % 10 == 0) {
        if (control.cancelled()) throw core::Cancelled();
        if (control.progress) control.progress(step, steps_);
      }
    }
    result.record.steps = steps_;
    result.record.options = {{"steps", std::to_string(steps_)}};
    result.counters = {{"points", std::to_string(result.scene.elements.size())}};
    return result;
  }
  // Which seed produced this first draw (the tests know the seeds).
  static std::uint64_t seed_of(double first) {
    for (std::uint64_t chain = 0; chain < 8; ++chain) {
      core::Random r(chain_seed(9, static_cast<int>(chain)));
      if (r.uniform() == first) return chain_seed(9, static_cast<int>(chain));
    }
    return 0;
  }

 private:
  long long steps_;
  std::uint64_t failing_seed_;
};

TEST(ChainSeed, FirstChainKeepsTheSeedOthersAreDistinct) {
  EXPECT_EQ(chain_seed(7, 0), 7u);
  std::set<std::uint64_t> seeds;
  for (std::uint64_t seed = 1; seed <= 20; ++seed)
    for (int chain = 0; chain < 20; ++chain) seeds.insert(chain_seed(seed, chain));
  EXPECT_EQ(seeds.size(), 400u);
}

TEST(RunChains, ResultsInChainOrderWhateverTheThreads) {
  const RandomPoints method(100);
  ChainOptions options;
  options.chains = 5;
  options.seed = 9;
  options.record.command = "test";
  options.threads = 1;
  const std::vector<SynthesisResult> one = run_chains(method, options);
  options.threads = 3;
  const std::vector<SynthesisResult> three = run_chains(method, options);
  ASSERT_EQ(one.size(), 5u);
  for (int c = 0; c < 5; ++c) {
    const SynthesisResult& r = one[static_cast<std::size_t>(c)];
    EXPECT_EQ(r.record.chain, c + 1);
    EXPECT_EQ(r.record.chains, 5);
    EXPECT_EQ(r.record.seed, 9u);
    EXPECT_EQ(r.record.chain_seed, chain_seed(9, c));
    EXPECT_EQ(r.record.method, "random-points");
    EXPECT_EQ(r.record.command, "test");
    EXPECT_EQ(r.record.option("steps"), "100");
    EXPECT_EQ(r.record.steps, 100);
    ASSERT_EQ(r.scene.elements.size(), three[static_cast<std::size_t>(c)].scene.elements.size());
    for (std::size_t i = 0; i < r.scene.elements.size(); ++i) {
      EXPECT_EQ(r.scene.elements[i].position,
                three[static_cast<std::size_t>(c)].scene.elements[i].position);
    }
  }
  EXPECT_NE(one[0].scene.elements[1].position, one[1].scene.elements[1].position);
}

TEST(RunChains, ProgressCountsEveryChainsSteps) {
  const RandomPoints method(200);
  ChainOptions options;
  options.chains = 4;
  options.threads = 2;
  std::atomic<long long> last_done{0}, last_total{0};
  long long calls = 0;
  options.progress = [&](long long done, long long total) {
    ++calls;  // never called at once (run_chains serialises the calls)
    last_done = done;
    last_total = total;
  };
  run_chains(method, options);
  EXPECT_EQ(calls, 4 * 20);
  EXPECT_EQ(last_total.load(), 800);
  EXPECT_EQ(last_done.load(), 800);
}

TEST(RunChains, CancellationStopsEveryChain) {
  const RandomPoints method(1000000);
  std::atomic<bool> cancel{true};
  ChainOptions options;
  options.chains = 2;
  options.cancel = &cancel;
  EXPECT_THROW(run_chains(method, options), core::Cancelled);
}

TEST(RunChains, AChainsErrorReachesTheCaller) {
  const RandomPoints method(10, chain_seed(9, 2));
  ChainOptions options;
  options.chains = 4;
  options.seed = 9;
  EXPECT_THROW(run_chains(method, options), core::UsageError);
  options.chains = 0;
  EXPECT_THROW(run_chains(method, options), core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::synthesis

// The README's and docs/synthesis.md's example, with the shape-process sampler: fit, then chains
// on a torus twice the exemplar's size; the chains' outputs do not depend on the thread count.

namespace shapeproc::synthesis {
namespace {

TEST(RunChains, ShapeProcessChainsAsTheDocsShowThem) {
  const geometry::Scene scene = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  fit::FitOptions fit_options;
  fit_options.quadrature = 16;
  const auto model = fit::fit_shape_process(scene, fit_options).model;
  const auto size = scene.window.sizes();
  const auto domain =
      geometry::Domain::from_sizes({2 * size.x(), 2 * size.y()}, geometry::Boundary::torus);
  sample::SamplerOptions options;
  options.iterations = 3000;
  const sample::ShapeProcessSampler sampler(model, domain, options);
  ChainOptions chains;
  chains.chains = 3;
  chains.seed = 1;
  chains.threads = 1;
  const std::vector<SynthesisResult> one = run_chains(sampler, chains);
  chains.threads = 3;
  const std::vector<SynthesisResult> three = run_chains(sampler, chains);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(one[c].record.method, "shape-process");
    EXPECT_EQ(one[c].record.steps, 3000);
    EXPECT_EQ(one[c].record.size, (std::vector<double>{2 * size.x(), 2 * size.y()}));
    EXPECT_EQ(one[c].record.boundary, geometry::Boundary::torus);
    ASSERT_EQ(one[c].scene.elements.size(), three[c].scene.elements.size());
    for (std::size_t i = 0; i < one[c].scene.elements.size(); ++i) {
      EXPECT_EQ(one[c].scene.elements[i].position, three[c].scene.elements[i].position);
    }
  }
  // Chain 1 is the one-off sampler with the run's seed.
  core::Random random(1);
  const sample::SampleResult alone = sampler.sample(random);
  ASSERT_EQ(alone.scene.elements.size(), one[0].scene.elements.size());
  for (std::size_t i = 0; i < alone.scene.elements.size(); ++i) {
    EXPECT_EQ(alone.scene.elements[i].position, one[0].scene.elements[i].position);
  }
}

}  // namespace
}  // namespace shapeproc::synthesis
