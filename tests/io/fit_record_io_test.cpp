#include "libshapeproc/io/fit_record_io.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace shapeproc::io {
namespace {

model::FitRecord full_record() {
  model::FitRecord r;
  r.window_min = {0, 0};
  r.window_max = {100, 50};
  r.elements = 40;
  r.edge = "periodic";
  r.quantiles = {0, 0.1, 0.2};
  r.quadrature = {false, 2304, 48, 2, 1, 9000, 1e-6};
  r.data_points = 40;
  r.log_pseudo_likelihood = -12.5;
  r.optimiser = "NLopt LD_LBFGS, then Newton";
  r.evaluations = 41;
  r.newton_steps = 2;
  r.seconds = {0.1, 0.2, 0.3, 0.4};
  r.version = "0.1.0";
  r.notes = {"a note"};
  model::LikelihoodRecord& e = r.likelihood.emplace();
  e.stationary_window = true;
  r.path = model::FitPath::likelihood_stationary_restarted;
  e.burn_in_kind = model::BurnIn::compressing;
  e.iterations = 7;
  e.converged = true;
  e.chains = 4;
  e.final_chains = 8;
  e.burn_in = 20000;
  e.steps = 50000;
  e.observe_every = 100;
  e.seed = 12345678901234ULL;
  e.attraction_prior_sd = 1.5;
  e.significance = 0.05;
  e.tolerance = 2.5;
  e.worst_r_hat = 1.02;
  e.seconds = 3.5;
  e.unbounded = {3};
  e.penalised = {1, 2};
  e.observed = {40, 12};
  e.expected = {39.5, 12.25};
  e.expected_standard_error = {0.5, 0.25};
  e.z = {1, -1};
  r.exemplar = "tile.svg";
  r.arguments = {"shapeproc", "fit", "tile.svg"};
  r.options = {{"reader.tile", "true"}, {"fit.quantiles", "0,0.1,0.2"}};
  r.tile_repeats = 3;
  r.edits = {{"m.json", {"shapeproc", "edit"}, {"scale-beta 2"}}};
  return r;
}

void expect_equal(const model::FitRecord& a, const model::FitRecord& b) {
  EXPECT_EQ(fit_record_json(a), fit_record_json(b));
  EXPECT_EQ(a.window_max, b.window_max);
  EXPECT_EQ(a.options, b.options);
  ASSERT_EQ(a.likelihood.has_value(), b.likelihood.has_value());
  if (a.likelihood) {
    EXPECT_EQ(a.likelihood->seed, b.likelihood->seed);
    EXPECT_EQ(a.likelihood->burn_in_kind, b.likelihood->burn_in_kind);
    EXPECT_EQ(a.likelihood->z, b.likelihood->z);
  }
  ASSERT_EQ(a.edits.size(), b.edits.size());
}

TEST(FitRecordIo, EveryFieldSurvivesTheRoundTrip) {
  const model::FitRecord r = full_record();
  const nlohmann::json written = fit_record_json(r);
  expect_equal(parse_fit_record(nlohmann::json::parse(written.dump())), r);
  EXPECT_EQ(written["estimator"]["burn_in_kind"], "compressing");
  model::FitRecord crystal = r;
  crystal.likelihood->burn_in_kind = model::BurnIn::crystal;  // a lattice's
  const nlohmann::json grown = fit_record_json(crystal);
  EXPECT_EQ(grown["estimator"]["burn_in_kind"], "crystal");
  expect_equal(parse_fit_record(grown), crystal);
  EXPECT_EQ(parse_fit_record(grown).likelihood->burn_in_kind, model::BurnIn::crystal);
  nlohmann::json unknown = grown;
  unknown["estimator"]["burn_in_kind"] = "warm";
  EXPECT_THROW(parse_fit_record(unknown), std::invalid_argument);
  // The path, typed: written by name, read back, and for a file without one, implied by its
  // estimator (a stationary window started from the pseudo-likelihood's estimate).
  EXPECT_EQ(written["path"],
            "likelihood, stationary window, restarted from the own window's estimate");
  nlohmann::json older = written;
  older.erase("path");
  EXPECT_EQ(parse_fit_record(older).path, model::FitPath::likelihood_stationary);
  older["estimator"]["window"] = "own";
  EXPECT_EQ(parse_fit_record(older).path, model::FitPath::likelihood_own_window);
  older.erase("estimator");
  EXPECT_EQ(parse_fit_record(older).path, model::FitPath::pseudo_likelihood);
  older["path"] = "by hand";
  EXPECT_THROW(parse_fit_record(older), std::invalid_argument);
  EXPECT_EQ(written["options"][0][0], "reader.tile");
  // Without the maximum likelihood, edits or repeats, those fields are absent.
  model::FitRecord plain = r;
  plain.likelihood.reset();
  plain.edits.clear();
  plain.tile_repeats = 0;
  const nlohmann::json j = fit_record_json(plain);
  for (const char* key : {"estimator", "edits", "tile_repeats"}) EXPECT_FALSE(j.contains(key));
  expect_equal(parse_fit_record(j), plain);
}

TEST(FitRecordIo, TheDensityIsTheRecordedExemplarsUntilAnEdit) {
  model::FitRecord r = full_record();
  EXPECT_FALSE(r.exemplar_density());  // full_record() has an edit
  r.edits.clear();
  EXPECT_DOUBLE_EQ(r.exemplar_density().value(), 40.0 / 5000.0);
  r.window_max = {100};  // a window of another dimension
  EXPECT_FALSE(r.exemplar_density());
}

// Older files kept the reader's and the fit's options as objects; a hand-edited record may hold
// fields of any type, which keep their defaults.
TEST(FitRecordIo, OlderLayoutsAndFieldsOfTheWrongTypeAreRead) {
  const nlohmann::json old = nlohmann::json::parse(R"({
    "elements": 34, "window": {"min": [0, 0], "max": [220, 220]},
    "reader": {"tile": false, "category_by": "fill"},
    "options": {"directions": 8, "quantiles": "0,0.1,0.2"},
    "estimator": {"method": "mcmc-mle", "window": "stationary", "iterations": "many",
                  "converged": true, "z": [1, "x"]},
    "notes": "not a list", "tile_repeats": 2.5})");
  const model::FitRecord r = parse_fit_record(old);
  EXPECT_EQ(r.elements, 34);
  const std::vector<std::pair<std::string, std::string>> options = {{"reader.category_by", "fill"},
                                                                    {"reader.tile", "false"},
                                                                    {"fit.directions", "8"},
                                                                    {"fit.quantiles", "0,0.1,0.2"}};
  EXPECT_EQ(r.options, options);
  ASSERT_TRUE(r.likelihood);
  EXPECT_TRUE(r.likelihood->stationary_window);
  EXPECT_TRUE(r.likelihood->converged);
  EXPECT_EQ(r.likelihood->iterations, 0);
  EXPECT_TRUE(r.likelihood->z.empty());
  EXPECT_TRUE(r.notes.empty());
  EXPECT_EQ(r.tile_repeats, 0);
  EXPECT_FALSE(parse_fit_record(nlohmann::json::parse(R"({"estimator": "mpl"})")).likelihood);
  EXPECT_EQ(parse_fit_record(nlohmann::json(5)).elements, 0);
}

}  // namespace
}  // namespace shapeproc::io
