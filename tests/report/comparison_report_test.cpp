// The assembled report: its files, what it returns, and the metrics' JSON.
#include "libshapeproc/report/comparison_report.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/report/metrics_json.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::report {
namespace {

const std::string kDots = testing::data_path("svg/dots-random.svg").string();

TEST(ComparisonReport, WritesThePageTheMetricsAndTheVerdicts) {
  const testing::TempDir dir;
  ComparisonRequest request;
  request.exemplar = kDots;
  request.outputs = {kDots};  // the exemplar as its own output: a copy at zero distance
  request.labels = {"itself"};
  request.directory = (dir.path() / "r").string();
  request.metrics.range = 40.0;
  const ComparisonReport report = write_comparison_report(request);
  EXPECT_EQ(report.index, (dir.path() / "r" / "index.html").string());
  for (const char* file : {"index.html", "metrics.json", "verdicts.md"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "r" / file)) << file;
  ASSERT_EQ(report.outputs.size(), 1u);
  const OutputSummary& o = report.outputs[0];
  EXPECT_EQ(o.label, "itself");
  EXPECT_EQ(o.file, kDots);
  EXPECT_DOUBLE_EQ(o.w1_nearest, 0.0);
  EXPECT_DOUBLE_EQ(o.w1_pairs, 0.0);
  EXPECT_EQ(o.colliding_pairs, 0u);
  EXPECT_NE(o.verdicts.find("repeats the exemplar"), std::string::npos) << o.verdicts;

  const auto metrics = nlohmann::json::parse(testing::read_file(dir.path() / "r" / "metrics.json"));
  EXPECT_EQ(metrics["exemplar"]["elements"], o.elements);
  EXPECT_EQ(metrics["outputs"][0]["elements"], o.elements);
  EXPECT_EQ(metrics["outputs"][0]["summary"], o.verdicts);
  EXPECT_EQ(metrics["options"]["range"], 40.0);
  EXPECT_EQ(metrics["options"]["boundary"], "auto");
  EXPECT_EQ(metrics["outputs"][0]["novelty"]["output"]["copy"], 1.0);
}

TEST(ComparisonReport, RefusesADirectoryThatIsAFileAndWritesNothing) {
  const testing::TempDir dir;
  const auto file = dir.write("taken", "x");
  ComparisonRequest request;
  request.exemplar = kDots;
  request.outputs = {kDots};
  request.directory = file.string();
  EXPECT_THROW(write_comparison_report(request), core::UsageError);
  EXPECT_EQ(testing::read_file(file), "x");
}

// An output whose chain ended empty, as `synthesize` writes it.
std::string write_empty_output(const testing::TempDir& dir) {
  geometry::Scene empty = io::read_scene(kDots, {});
  empty.elements.clear();
  synthesis::SynthesisRecord record;
  record.method = "shape-process";
  record.set_domain(geometry::Domain::from_sizes({200, 200}, geometry::Boundary::torus));
  const auto file = dir.file("empty.svg");
  io::write_scene(empty, file, io::synthesis_provenance(record));
  return file.string();
}

TEST(ComparisonReport, AnEmptyOutputIsNamedAndLeftOffThePage) {
  const testing::TempDir dir;
  const std::string empty = write_empty_output(dir);
  ComparisonRequest request;
  request.exemplar = kDots;
  request.outputs = {empty, kDots};
  request.directory = (dir.path() / "r").string();
  const ComparisonReport report = write_comparison_report(request);
  ASSERT_EQ(report.outputs.size(), 1u);
  EXPECT_EQ(report.outputs[0].file, kDots);
  EXPECT_EQ(report.empty_outputs, std::vector<std::string>{empty});
  // Every output empty: nothing to compare, and nothing written.
  request.outputs = {empty};
  request.directory = (dir.path() / "none").string();
  EXPECT_THROW(write_comparison_report(request), core::InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "none"));
  // An empty output read as an exemplar is refused too.
  EXPECT_THROW(evaluation::read_exemplar(empty, {}, {}), core::InputError);
}

TEST(MetricsJson, NamesTheOptionsAsTheCommandsDo) {
  evaluation::MetricOptions options;
  options.boundary = evaluation::BoundaryChoice::torus;
  options.edge = metrics::EdgeTreatment::border;
  options.direction = geometry::DirectionKind::centroid;
  options.directions = 4;
  const nlohmann::json j = metric_options_json(options);
  EXPECT_EQ(j["boundary"], "torus");
  EXPECT_EQ(j["edge"], "border");
  EXPECT_EQ(j["direction"], "centroid");
  EXPECT_EQ(j["directions"], 4);
  EXPECT_EQ(metric_options_json({})["boundary"], "auto");
  EXPECT_EQ(metric_options_json({})["edge"], "auto");
}

}  // namespace
}  // namespace shapeproc::report
