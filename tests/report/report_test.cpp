#include <gtest/gtest.h>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/report/html_report.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::report {
namespace {

TEST(HtmlReport, WritesPagePicturesAtOneScaleAndMetrics) {
  const testing::TempDir dir;
  const geometry::Scene exemplar = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  geometry::Scene output = exemplar;  // an "output" twice as wide: the exemplar twice, side by side
  const double width = exemplar.window.sizes().x();
  output.window.max().x() += width;
  for (const geometry::Element& e : exemplar.elements) {
    geometry::Element moved = e;
    moved.position.x() += width;
    output.elements.push_back(moved);
  }
  const metrics::SceneStatistics reference =
      metrics::compute_statistics(exemplar, {}, core::Random(1));
  metrics::StatisticsOptions options;
  options.range = reference.range;
  const metrics::SceneStatistics stats =
      metrics::compute_statistics(output, options, core::Random(1));
  const metrics::Comparison comparison = metrics::compare(stats, reference);
  const metrics::NeighbourhoodDistance neighbourhood = metrics::average_neighbourhood_distance(
      output, geometry::Boundary::open, exemplar, geometry::Boundary::open);

  Report report;
  report.exemplar = {"dots-random.svg", &exemplar, &reference, nullptr, nullptr, ""};
  report.outputs.push_back(
      {"twice.svg", &output, &stats, &comparison, &neighbourhood, "shapeproc test, seed 1"});
  report.command = "shapeproc report dots-random.svg twice.svg";
  write_report(report, dir.path() / "r");

  const std::string html = testing::read_file(dir.path() / "r" / "index.html");
  EXPECT_NE(html.find("dots-random.svg"), std::string::npos);
  EXPECT_NE(html.find("twice.svg"), std::string::npos);
  EXPECT_NE(html.find("shapeproc test, seed 1"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);  // nothing fetched from the network
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  const geometry::Raster a = io::read_grayscale_png(dir.path() / "r" / "exemplar.png");
  const geometry::Raster b = io::read_grayscale_png(dir.path() / "r" / "output-1.png");
  // One scale: the output, twice as wide, has twice the pixels across.
  EXPECT_NEAR(b.width, 2 * a.width, 2);
  EXPECT_EQ(a.height, b.height);
  // Copies of the exemplar side by side: the same neighbourhoods inside, a small distance.
  EXPECT_LT(neighbourhood.normalised, 0.5);
}

TEST(HtmlReport, MissingStatisticsAreAnError) {
  const testing::TempDir dir;
  Report report;
  EXPECT_THROW(write_report(report, dir.path() / "r"), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "r" / "index.html"));
}

}  // namespace
}  // namespace shapeproc::report
