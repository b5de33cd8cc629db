// synthesize --method ma-em|davison|ijiri: the neighbourhood EM, region growing and seed-and-grow
// through the same
// domain, chains, outputs, records and errors as the shape process.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/test_support.hpp"
#include "tests/tools/cli_test_support.hpp"

namespace shapeproc::cli {
namespace {

TEST(CliSynthesizeMaEm, OutputsCarryTheMethodsRecordAndRepeat) {
  const testing::TempDir dir;
  const std::string out = dir.file("em.svg").string();
  const std::string trace = dir.file("em.csv").string();
  const Result r =
      run_cli({"synthesize", data("svg/dashes-rows.svg"), "--method", "ma-em", "-o", out, "--size",
               "300,200", "--seed", "3", "--iterations", "4", "--trace", trace, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("synthesised "), std::string::npos) << r.out;
  const std::string svg = testing::read_file(out);
  for (const char* part : {"&quot;method&quot;:&quot;neighbourhood-em&quot;", "&quot;seed&quot;:3",
                           "em.neighbourhood_rings", "em.reconstruction", "--method"})
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  const std::string csv = testing::read_file(trace);
  EXPECT_EQ(csv.find("# shapeproc synthesize neighbourhood-em seed 3 chain 1\niteration,elements,"
                     "energy\n0,"),
            0u)
      << csv.substr(0, 90);
  // Same seed, same bytes after the metadata.
  const std::string again = dir.file("again.svg").string();
  ASSERT_EQ(run_cli({"synthesize", data("svg/dashes-rows.svg"), "--method", "ma-em", "-o", again,
                     "--size", "300,200", "--seed", "3", "--iterations", "4", "--quiet"})
                .code,
            0);
  const auto body = [](const std::string& text) { return text.substr(text.find("</metadata>")); };
  EXPECT_EQ(body(testing::read_file(again)), body(svg));
  // stats reads the record back: the output's own torus.
  const Result stats = run_cli({"stats", out, "--against", data("svg/dashes-rows.svg"), "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_EQ(nlohmann::json::parse(stats.out).at("boundary"), "torus");
}

// The tile baseline: the bubbles tile repeated over 3 x 3 tiles (--size 3W,3H), whatever the seed;
// `stats
// --against` finds it a copy (every novelty measure 1, against chance levels far below) and says it
// repeats the exemplar. Options of the fitted and grown methods are refused.
TEST(CliSynthesizeTile, TheExemplarRepeatedIsTheBaselineStatsCallsACopy) {
  const testing::TempDir dir;
  const std::string tile = data("third-party/hero-patterns/bubbles.svg");
  const std::string out = dir.file("tile.svg").string();
  const Result r = run_cli({"synthesize", tile, "--tile", "--method", "tile", "-o", out, "--size",
                            "3W,3H", "--seed", "5", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("tile: the exemplar repeated over the output"), std::string::npos) << r.out;
  const Result stats = run_cli({"stats", out, "--against", tile, "--tile", "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  const nlohmann::json j = nlohmann::json::parse(stats.out);
  EXPECT_EQ(j.at("elements"), 9 * 17);
  const nlohmann::json& novelty = j.at("novelty");
  for (const char* measure : {"copy", "patch", "largest_patch", "repetition"}) {
    EXPECT_DOUBLE_EQ(novelty.at("output").at(measure).get<double>(), 1.0) << measure;
    EXPECT_LT(novelty.at("chance").at(measure).get<double>(), 0.2) << measure;
  }
  EXPECT_TRUE(novelty.at("repeats_exemplar").get<bool>());
  const Result text = run_cli({"stats", out, "--against", tile, "--tile"});
  EXPECT_NE(text.out.find("repeats the exemplar"), std::string::npos) << text.out;
  expect_one_line_error(run_cli({"synthesize", tile, "--tile", "--method", "tile", "-o",
                                 dir.file("x.svg").string(), "--size", "300,300", "--ratio", "3"}),
                        2, "--ratio");
  expect_one_line_error(run_cli({"synthesize", tile, "--tile", "--method", "tile", "-o",
                                 dir.file("y.svg").string(), "--size", "3H,3W"}),
                        2, "--size");
}

TEST(CliSynthesizeMaEm, OptionsOfTheOtherMethodAndNonsenseAreRefused) {
  const testing::TempDir dir;
  const std::string out = dir.file("em.svg").string();
  const std::string exemplar = data("svg/dots-random.svg");
  const auto em = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"synthesize", exemplar, "--method", "ma-em",
                                     "-o",         out,      "--size",   "100,100"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args);
  };
  expect_one_line_error(em({"--estimator", "mpl"}), 2, "--estimator is for --method shape-process");
  expect_one_line_error(em({"--shift-probability", "0.5"}), 2, "--shift-probability");
  expect_one_line_error(
      run_cli({"synthesize", exemplar, "-o", out, "--size", "100,100", "--k", "3", "--force"}), 2,
      "--k is for --method ma-em");
  expect_one_line_error(em({"--samples-per-element", "0"}), 2, "--samples-per-element");
  expect_one_line_error(em({"--orientation-field", "north"}), 2, "--orientation-field");
  expect_one_line_error(em({"--reconstruction", "bend"}), 2, "--reconstruction");
  expect_one_line_error(em({"--method", "copy"}), 2, "--method");
  expect_one_line_error(em({"--physics-steps", "3"}), 2, "--physics");
  expect_one_line_error(em({"--physics", "--physics-steps", "0"}), 2, "--physics-steps");
  expect_one_line_error(
      run_cli({"synthesize", exemplar, "-o", out, "--size", "100,100", "--physics"}), 2,
      "--physics is for --method ma-em");
  expect_one_line_error(
      run_cli({"synthesize", exemplar, "--method", "ma-em", "-o", out, "--size", "10,10,10"}), 2,
      "for a 2D model");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliSynthesizeMaEm, DomainShapesAndOrientationFields) {
  const testing::TempDir dir;
  const std::string out = dir.file("em.svg").string();
  const Result r =
      run_cli({"synthesize", data("svg/dots-random.svg"), "--method", "ma-em", "-o", out, "--size",
               "400,400", "--domain", data("maps/star.svg"), "--orientation-field", "30",
               "--reconstruction", "tps", "--png", dir.file("em.png").string(), "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("em.png")));
  const std::string svg = testing::read_file(out);
  EXPECT_NE(svg.find("30 degrees"), std::string::npos);
  EXPECT_NE(svg.find("&quot;boundary&quot;:&quot;open&quot;"), std::string::npos);
}

TEST(CliSynthesizeDavison, GrowsATileWithItsRecordAndTrace) {
  const testing::TempDir dir;
  const std::string out = dir.file("grown.svg").string();
  const std::string trace = dir.file("grown.csv").string();
  const std::string tile = data("third-party/hero-patterns/bubbles.svg");
  const Result r = run_cli({"synthesize", tile, "--tile", "--method", "davison", "-o", out,
                            "--size", "300,300", "--seed", "2", "--trace", trace, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = testing::read_file(out);
  for (const char* part : {"&quot;method&quot;:&quot;region-growing&quot;", "growth.ratio",
                           "growth.neighbourhood_rings"})
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  EXPECT_EQ(testing::read_file(trace).find("# shapeproc synthesize region-growing seed 2 chain 1\n"
                                           "round,elements,energy\n"),
            0u);
  // 17 elements per 100 x 100 tile: 9 tiles' worth.
  const Result stats = run_cli({"stats", out, "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_NEAR(nlohmann::json::parse(stats.out).at("elements").get<double>(), 153.0, 15.0);
}

TEST(CliSynthesizeDavison, OptionsOfOtherMethodsAreRefused) {
  const testing::TempDir dir;
  const std::string out = dir.file("x.svg").string();
  const std::string exemplar = data("svg/dots-random.svg");
  const auto grow = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"synthesize", exemplar, "--method", "davison", "-o",
                                     out,          "--size", "100,100",  "--force"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args);
  };
  expect_one_line_error(grow({"--physics"}), 2, "--physics is for --method ma-em");
  expect_one_line_error(grow({"--estimator", "mpl"}), 2,
                        "--estimator is for --method shape-process");
  expect_one_line_error(grow({"--ratio", "1"}), 2, "--ratio");
  expect_one_line_error(grow({"--overlap", "none"}), 2, "--method davison tests circles or shapes");
  // --overlap shapes reaches the method: its record says so.
  ASSERT_EQ(grow({"--overlap", "shapes", "--quiet"}).code, 0);
  EXPECT_NE(testing::read_file(out).find("growth.overlap&quot;,&quot;shapes"), std::string::npos);
  expect_one_line_error(grow({"--iterations", "5"}), 2, "--iterations");
  expect_one_line_error(
      run_cli({"synthesize", exemplar, "-o", out, "--size", "100,100", "--ratio", "3", "--force"}),
      2, "--ratio is for --method davison");
  expect_one_line_error(
      run_cli({"synthesize", exemplar, "-o", out, "--size", "100,100", "--k", "3", "--force"}), 2,
      "--k is for --method ma-em or davison");
}

TEST(CliSynthesizeDavison, APaletteGrowsTwoExemplarsSideBySide) {
  const testing::TempDir dir;
  const std::string out = dir.file("palette.svg").string();
  const std::string crescents = data("svg/crescents-grid.svg");
  const std::string dots = data("svg/dots-random.svg");
  const auto grow = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"synthesize", crescents, "--method", "davison", "-o",     out,
                                     "--size",     "600,300", "--seed",   "1",       "--force"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args);
  };
  const Result r = grow({"--palette", dots, "--palette-neighbourhood", "1.5", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  // Each exemplar's neighbourhood radius at its own spacing and rings.
  EXPECT_NE(r.out.find("region growing: 25 exemplar elements"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("palette: 30 exemplar elements"), std::string::npos) << r.out;
  const std::string svg = testing::read_file(out);
  for (const char* part : {"&quot;palette&quot;", "growth.palette&quot;,&quot;2", "dots-random"})
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  const Result stats = run_cli({"stats", out, "--category-by", "fill", "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_GT(nlohmann::json::parse(stats.out).at("elements").get<double>(), 100.0);

  expect_one_line_error(grow({"--palette-neighbourhood", "2"}), 2, "they need --palette");
  expect_one_line_error(grow({"--palette", dir.write("bad.svg", "<svg").string()}), 2, "bad.svg");
  expect_one_line_error(run_cli({"synthesize", crescents, "-o", out, "--size", "100,100",
                                 "--palette", dots, "--force"}),
                        2, "--palette is for --method davison");
}

TEST(CliSynthesizeDavison, A3DOutputIsMeasuredOnItsDomain) {
  // A mesh file has no window: its metrics take the domain box from its record, not the
  // elements' bounds (which wrapped elements overhang on a torus).
  const testing::TempDir dir;
  const std::string out = dir.file("grown.obj").string();
  const Result r =
      run_cli({"synthesize", data("mesh/pebbles.obj"), "--method", "davison", "--neighbourhood",
               "1", "--size", "22,22,5", "--seed", "1", "-o", out, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Result stats = run_cli({"stats", out, "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_NEAR(nlohmann::json::parse(stats.out).at("window_measure").get<double>(), 22.0 * 22 * 5,
              1e-9);
}

TEST(CliSynthesizeHybrid, RegionGrowingThenTheSamplerWithItsRecord) {
  const testing::TempDir dir;
  const std::string out = dir.file("hybrid.svg").string();
  const std::string dots = data("svg/dots-random.svg");
  const Result r =
      run_cli({"synthesize", dots, "--method", "hybrid", "--start-from", "davison", "-o", out,
               "--size", "300,300", "--seed", "2", "--iterations", "3000", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("hybrid: davison's output, then the shape-process sampler"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("start elements kept"), std::string::npos) << r.out;
  const std::string svg = testing::read_file(out);
  for (const char* part : {"&quot;method&quot;:&quot;hybrid&quot;", "hybrid.start_from",
                           "region-growing", "start.growth.ratio"})
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  expect_one_line_error(
      run_cli({"synthesize", dots, "-o", out, "--size", "100,100", "--start-from", "ma-em"}), 2,
      "--start-from is for --method hybrid");
  expect_one_line_error(run_cli({"synthesize", dots, "--method", "hybrid", "-o", out, "--size",
                                 "100,100", "--ratio", "3"}),
                        2, "--ratio is for --method davison");
}

TEST(CliSynthesizeIjiri, GrowsATileWithFlipsSeedsAndItsRecord) {
  const testing::TempDir dir;
  const std::string out = dir.file("seeded.svg").string();
  const std::string seeds = dir.write("seeds.txt", "# spray\n150 150\n40,60\n").string();
  const std::string tile = data("third-party/hero-patterns/bubbles.svg");
  const Result r =
      run_cli({"synthesize", tile, "--tile", "--method", "ijiri", "-o", out, "--size", "300,300",
               "--seed", "2", "--seeds", seeds, "--rotation", "best", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = testing::read_file(out);
  for (const char* part : {"&quot;method&quot;:&quot;seed-and-grow&quot;", "ijiri.rotation",
                           "&quot;ijiri.seeds&quot;,&quot;2&quot;"})
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  // 17 elements per 100 x 100 tile: 9 tiles' worth, and more where the two fronts meet out of
  // phase.
  const Result stats = run_cli({"stats", out, "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_NEAR(nlohmann::json::parse(stats.out).at("elements").get<double>(), 160.0, 16.0);
}

TEST(CliSynthesizeIjiri, BadFilesAndFlagsGetOneLine) {
  const testing::TempDir dir;
  const std::string out = dir.file("x.svg").string();
  const std::string exemplar = data("svg/dots-random.svg");
  const std::string flips = dir.file("flips.txt").string();
  const auto grow = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"synthesize", exemplar, "--method", "ijiri",
                                     "-o",         out,      "--size",   "100,100"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args);
  };
  dir.write("flips.txt", "0 1\n2 x\n");
  expect_one_line_error(grow({"--edge-flips", flips}), 2, "flips.txt:2:");
  dir.write("flips.txt", "0 999\n");
  expect_one_line_error(grow({"--edge-flips", flips}), 2, "0-999");
  expect_one_line_error(grow({"--rotation", "flow-field"}), 2, "--orientation-field");
  expect_one_line_error(grow({"--weights", "1,2"}), 2, "--weights");
  expect_one_line_error(grow({"--show-connectivity", "c.png"}), 2, "--show-connectivity");
  expect_one_line_error(grow({"--overlap", "round"}), 2, "--overlap");
  expect_one_line_error(grow({"--priority", "nope=2"}), 2, "no category 'nope'");
  expect_one_line_error(grow({"--ratio", "3"}), 2, "--ratio is for --method davison");
  expect_one_line_error(grow({"--iterations", "5"}), 2, "--iterations");
  EXPECT_FALSE(std::filesystem::exists(out));
  expect_one_line_error(
      run_cli({"synthesize", exemplar, "-o", out, "--size", "100,100", "--rotation", "best"}), 2,
      "--rotation is for --method ijiri");
}

}  // namespace
}  // namespace shapeproc::cli
