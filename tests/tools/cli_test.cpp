// The command line, run in-process: exit codes, one-line errors, nothing half-written.
#include "tools/cli/cli.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>
#include <tuple>

#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/render/raster.hpp"
#include "libshapeproc/synthesis/output_check.hpp"
#include "tests/test_support.hpp"
#include "tests/tools/cli_test_support.hpp"

namespace shapeproc::cli {
namespace {

TEST(Cli, VersionAndHelp) {
  const Result version = run_cli({"--version"});
  EXPECT_EQ(version.code, 0);
  EXPECT_EQ(version.out, std::string("shapeproc ") + SHAPEPROC_VERSION + "\n");
  const Result help = run_cli({"--help"});
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("info"), std::string::npos);
  EXPECT_NE(help.out.find("convert"), std::string::npos);
  const Result info_help = run_cli({"info", "--help"});
  EXPECT_EQ(info_help.code, 0);
  EXPECT_NE(info_help.out.find("--category-by"), std::string::npos);
}

// docs/commands.md holds every command's --help as the command prints it (written by
// scripts/command-docs.sh): a changed option without a rewritten page fails here.
TEST(CliHelp, DocsCommandsHoldsEveryCommandsHelp) {
  const std::string page =
      testing::read_file(testing::data_path("../docs/commands.md").lexically_normal());
  const Result top = run_cli({"--help"});
  ASSERT_EQ(top.code, 0);
  EXPECT_NE(page.find("```text\n" + top.out + "```"), std::string::npos) << "shapeproc --help";
  int commands = 0;
  for (const char* command : {"info", "convert", "measure", "fidelity", "fit", "show", "sample",
                              "synthesize", "edit", "stats", "report", "compare"}) {
    const Result help = run_cli({command, "--help"});
    ASSERT_EQ(help.code, 0) << command;
    EXPECT_NE(page.find("## " + std::string(command) + "\n\n```text\n" + help.out + "```"),
              std::string::npos)
        << command << ": rerun bash scripts/command-docs.sh";
    EXPECT_NE(top.out.find(std::string("  ") + command + " "), std::string::npos) << command;
    ++commands;
  }
  EXPECT_EQ(commands, 12);
}

TEST(Cli, NonsenseFlags) {
  expect_one_line_error(run_cli({}), 2, "subcommand");
  expect_one_line_error(run_cli({"frobnicate"}), 2, "frobnicate");
  expect_one_line_error(run_cli({"info", data("svg/dots-random.svg"), "--bogus"}), 2, "--bogus");
  expect_one_line_error(run_cli({"info", data("svg/dots-random.svg"), "--category-by", "colour"}),
                        2, "--category-by");
  expect_one_line_error(run_cli({"info", data("points/clusters.csv"), "--window", "0,1,2"}), 2,
                        "--window");
  expect_one_line_error(run_cli({"info", data("mesh/pebbles.obj"), "--split", "faces"}), 2,
                        "--split");
  expect_one_line_error(run_cli({"convert", data("svg/dots-random.svg")}), 2, "--output");
  expect_one_line_error(
      run_cli({"fit", data("svg/dots-random.svg"), "--data-weight", "1", "-o", "unused.json"}), 2,
      "--data-weight");
  for (const char* share : {"1", "-0.1", "often"})
    expect_one_line_error(
        run_cli({"fit", data("svg/dots-random.svg"), "--near-births", share, "-o", "unused.json"}),
        2, "--near-births");
}

TEST(Cli, InfoTextAndJson) {
  const Result text = run_cli({"info", data("svg/two-kinds.svg"), "--category-by", "fill"});
  EXPECT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("elements:   34"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("#e53e3e: 17"), std::string::npos) << text.out;
  const Result json = run_cli({"info", data("mesh/pebbles.obj"), "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const nlohmann::json parsed = nlohmann::json::parse(json.out);
  EXPECT_EQ(parsed["dimension"], 3);
  EXPECT_EQ(parsed["element_count"], 12);
  EXPECT_EQ(parsed["elements"][0]["triangles"], 80);
  EXPECT_EQ(parsed["elements"][0]["bbox"]["min"].size(), 3u);
}

TEST(Cli, ConvertRecordsItsParameters) {
  const testing::TempDir dir;
  const std::string out = dir.file("sub/dots.svg").string();
  const Result r = run_cli({"convert", data("svg/dots-random.svg"), "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = testing::read_file(out);
  EXPECT_NE(svg.find("&quot;command&quot;:&quot;convert&quot;"), std::string::npos);
  EXPECT_NE(svg.find("category_by"), std::string::npos);
  const Result again = run_cli({"info", out});
  EXPECT_NE(again.out.find("elements:   30"), std::string::npos);
}

struct BadRun {
  const char* name;
  std::vector<std::string> args;  // "IN:" prefix = file written in the temp dir with this text
  const char* message;
};

TEST(Cli, BadInputExitsTwoAndLeavesTheOutputAlone) {
  const testing::TempDir dir;
  dir.write("malformed.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<g>\n</svg>\n");
  dir.write("nowindow.csv", "x,y\n1,2\n");
  dir.write("nm.off",
            "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  dir.write("notes.txt", "hello\n");
  const std::string previous = "previous contents\n";
  const std::string out_svg = dir.write("out.svg", previous).string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"convert", dir.file("malformed.svg").string(), "-o", out_svg},
       "malformed.svg:3: malformed XML"},
      {{"convert", dir.file("missing.svg").string(), "-o", out_svg}, "missing.svg: no such file"},
      {{"convert", dir.file("nowindow.csv").string(), "-o", out_svg},
       "nowindow.csv: a CSV point pattern needs --window"},
      {{"convert", dir.file("nm.off").string(), "-o", out_svg}, "nm.off: non-manifold"},
      {{"convert", dir.file("notes.txt").string(), "-o", out_svg}, "unknown format"},
      {{"convert", data("mesh/pebbles.obj"), "-o", out_svg}, "2D scenes only"},
  };
  for (const Case& c : cases) {
    expect_one_line_error(run_cli(c.args), 2, c.message);
    EXPECT_EQ(testing::read_file(out_svg), previous);
  }
  const std::string out_bmp = dir.file("out.bmp").string();
  expect_one_line_error(run_cli({"convert", data("svg/dots-random.svg"), "-o", out_bmp}), 2,
                        "unknown output format");
  EXPECT_FALSE(std::filesystem::exists(out_bmp));
  // Nothing else was left in the directory (no temporary files).
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 5u);
}

}  // namespace
}  // namespace shapeproc::cli

namespace shapeproc::cli {
namespace {

TEST(CliFit, FitShowAndPlot) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string();
  const Result fit = run_cli({"fit", data("svg/two-kinds.svg"), "--category-by", "fill",
                              "--quadrature", "8", "-o", model});
  ASSERT_EQ(fit.code, 0) << fit.err;
  EXPECT_NE(fit.out.find("intensity beta"), std::string::npos);
  EXPECT_NE(fit.out.find("interaction #e53e3e - #3182ce"), std::string::npos) << fit.out;
  EXPECT_NE(fit.out.find("log pseudo-likelihood"), std::string::npos);
  EXPECT_NE(fit.out.find("time: proxies"), std::string::npos);
  const nlohmann::json saved = nlohmann::json::parse(testing::read_file(model));
  EXPECT_EQ(saved["format"], "shapeproc-model");
  EXPECT_EQ(saved["fit"]["arguments"][1], "fit");
  EXPECT_EQ(saved["shapes"].size(), 34u);
  const std::string plot = dir.file("plot.svg").string();
  const Result show = run_cli({"show", model, "--plot", plot});
  ASSERT_EQ(show.code, 0) << show.err;
  EXPECT_NE(show.out.find("intensity beta"), std::string::npos);
  EXPECT_NE(testing::read_file(plot).find("<svg"), std::string::npos);
}

// The quadrature and the maximum likelihood's chains run on --threads threads; the model does not
// depend on them.
TEST(CliFit, TheModelDoesNotDependOnTheThreads) {
  const testing::TempDir dir;
  std::vector<nlohmann::json> models;
  for (const char* threads : {"1", "3"}) {
    const std::string model = dir.file(std::string("m") + threads + ".json").string();
    const Result r = run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "12",
                              "--mle-steps", "5000", "--threads", threads, "-o", model});
    ASSERT_EQ(r.code, 0) << r.err;
    models.push_back(nlohmann::json::parse(testing::read_file(model)));
  }
  EXPECT_EQ(models[0].at("categories"), models[1].at("categories"));
  EXPECT_EQ(models[0].at("interaction"), models[1].at("interaction"));
}

TEST(CliFit, BadInputAndOptions) {
  const testing::TempDir dir;
  dir.write("broken.json", "{\"format\": \"shapeproc-model\",\n \"version\": 1,\n}");
  expect_one_line_error(run_cli({"show", dir.file("broken.json").string()}), 2,
                        "broken.json:3: malformed JSON");
  expect_one_line_error(run_cli({"fit", data("svg/dots-random.svg"), "-o",
                                 dir.file("m.json").string(), "--quantiles", "0.2,0.1"}),
                        2, "quantile orders must increase");
  expect_one_line_error(
      run_cli({"fit", data("svg/dots-random.svg"), "-o", dir.file("m.json").string(), "--quantiles",
               "0,0.1", "--thresholds", "1,2"}),
      2, "excludes");
  expect_one_line_error(
      run_cli({"fit", data("svg/dots-random.svg"), "-o", dir.file("m.txt").string()}), 2, ".json");
  expect_one_line_error(run_cli({"fit", data("svg/dots-random.svg"), "-o",
                                 dir.file("m.json").string(), "--directions", "3"}),
                        2, "even number");
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.json")));
}

}  // namespace
}  // namespace shapeproc::cli

namespace shapeproc::cli {
namespace {

TEST(CliSample, SampleRecordsSeedAndParameters) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string();
  ASSERT_EQ(run_cli({"fit", data("third-party/hero-patterns/bubbles.svg"), "--split-subpaths",
                     "--quadrature", "8", "-o", model})
                .code,
            0);
  const std::string out = dir.file("out.svg").string();
  const Result r = run_cli({"sample", model, "-o", out, "--size", "200,200", "--seed", "7",
                            "--iterations", "3000", "--trace", dir.file("trace.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = testing::read_file(out);
  EXPECT_NE(svg.find("&quot;seed&quot;:7"), std::string::npos);
  EXPECT_NE(svg.find("viewBox=\"0 0 200 200\""), std::string::npos);
  const std::string trace = testing::read_file(dir.file("trace.csv"));
  EXPECT_EQ(trace.rfind(
                "# shapeproc sample shape-process seed 7 chain 1\nstep,elements,log_density\n", 0),
            0u)
      << trace.substr(0, 80);
  // Same seed, same output.
  const std::string again = dir.file("again.svg").string();
  ASSERT_EQ(run_cli({"sample", model, "-o", again, "--size", "200,200", "--seed", "7",
                     "--iterations", "3000"})
                .code,
            0);
  const auto body = [](const std::string& text) { return text.substr(text.find("</metadata>")); };
  EXPECT_EQ(body(testing::read_file(again)), body(svg));
  expect_one_line_error(run_cli({"sample", model, "-o", out, "--size", "200"}), 2, "--size");
  expect_one_line_error(
      run_cli({"sample", dir.file("none.json").string(), "-o", out, "--size", "1,1", "--force"}), 2,
      "no such file");
  // An output that exists is not overwritten without --force.
  expect_one_line_error(run_cli({"sample", model, "-o", out, "--size", "200,200"}), 2,
                        "exists: give --force");
  // A chain that ends empty at its automatic stop where the exemplar's density asks for elements
  // writes nothing.
  // (The fitted model with a β too small to hold anything, its fit record kept.)
  nlohmann::json document = nlohmann::json::parse(testing::read_file(model));
  for (auto& category : document["categories"]) category["beta"] = 1e-12;
  const std::string faint = dir.write("faint.json", document.dump()).string();
  const std::string empty = dir.file("empty.svg").string();
  expect_one_line_error(run_cli({"sample", faint, "-o", empty, "--size", "200,200", "--png",
                                 dir.file("empty.png").string()}),
                        2, "ended empty where the exemplar's density gives");
  EXPECT_FALSE(std::filesystem::exists(empty));
  EXPECT_FALSE(std::filesystem::exists(dir.file("empty.png")));
}

TEST(CliSample, ChainsDomainsMapsAndPictures) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string();
  ASSERT_EQ(run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "8", "-o", model}).code,
            0);
  // Chains: suffixed outputs, the same whatever the thread count.
  for (const char* threads : {"1", "2"}) {
    const Result r = run_cli(
        {"sample", model, "-o", dir.file(std::string("t") + threads + ".csv").string(), "--size",
         "300,300", "--chains", "2", "--threads", threads, "--iterations", "4000", "--seed", "9"});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const auto body = [](const std::string& text) {
    return text.substr(text.find("\nx,") == std::string::npos ? 0 : text.find("\nx,"));
  };
  EXPECT_EQ(body(testing::read_file(dir.file("t1-1.csv"))),
            body(testing::read_file(dir.file("t2-1.csv"))));
  EXPECT_EQ(body(testing::read_file(dir.file("t1-2.csv"))),
            body(testing::read_file(dir.file("t2-2.csv"))));
  EXPECT_NE(body(testing::read_file(dir.file("t1-1.csv"))),
            body(testing::read_file(dir.file("t1-2.csv"))));
  // A star-shaped domain and a gradient map, with a PNG rendering.
  const std::string star = dir.file("star.svg").string(), png = dir.file("star.png").string();
  const Result shaped =
      run_cli({"sample", model, "-o", star, "--size", "400,400", "--domain", data("maps/star.svg"),
               "--intensity", data("maps/gradient.png"), "--png", png, "--iterations", "20000"});
  ASSERT_EQ(shaped.code, 0) << shaped.err;
  EXPECT_EQ(testing::read_file(png).substr(0, 4), "\x89PNG");
  EXPECT_NE(testing::read_file(star).find("star.svg"),
            std::string::npos);  // the domain is recorded
  // Bad domains and combinations.
  expect_one_line_error(run_cli({"sample", model, "-o", star, "--size", "400,400", "--domain",
                                 data("maps/star.svg"), "--boundary", "torus", "--force"}),
                        2, "--boundary torus");
  const std::string not_png = dir.write("fake.png", "not a png").string();
  expect_one_line_error(run_cli({"sample", model, "-o", dir.file("x.svg").string(), "--size",
                                 "40,40", "--intensity", not_png}),
                        2, "fake.png");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.svg")));
  expect_one_line_error(run_cli({"sample", model, "-o", star, "--size", "40,40", "--domain",
                                 data("svg/dots-random.csv"), "--force"}),
                        2, "--domain");
  // Chains' outputs and records are never overwritten without --force: a second run of 2 chains
  // refuses, naming the first file and counting the others.
  expect_one_line_error(run_cli({"sample", model, "-o", dir.file("t1.csv").string(), "--size",
                                 "300,300", "--chains", "2", "--iterations", "10"}),
                        2, "t1-1.csv exists (and 3 more of this run's outputs)");
  expect_one_line_error(run_cli({"sample", model, "-o", dir.file("p.png").string(), "--png",
                                 dir.file("p.png").string(), "--size", "300,300"}),
                        2, "twice");
}

TEST(CliEdit, EditsAreAppliedValidatedAndRecorded) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string(), edited = dir.file("e.json").string();
  ASSERT_EQ(run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "8", "-o", model}).code,
            0);
  const Result r = run_cli({"edit", model, "-o", edited, "--gamma", "0:*:1=0.25", "--beta",
                            "default=0.002", "--scale-thresholds", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json before = nlohmann::json::parse(testing::read_file(model));
  const nlohmann::json after = nlohmann::json::parse(testing::read_file(edited));
  EXPECT_DOUBLE_EQ(after["categories"][0]["beta"].get<double>(), 0.002);
  for (std::size_t a = 0; a < 4; ++a) {
    EXPECT_DOUBLE_EQ(after["interaction"][0]["axes"][a]["gammas"][0].get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(after["interaction"][0]["axes"][a]["gammas"][1].get<double>(),
                     before["interaction"][0]["axes"][a]["gammas"][1].get<double>());
    EXPECT_DOUBLE_EQ(after["interaction"][0]["axes"][a]["thresholds"][2].get<double>(),
                     2 * before["interaction"][0]["axes"][a]["thresholds"][2].get<double>());
  }
  EXPECT_NE(testing::read_file(edited).find("scale-thresholds 2"), std::string::npos);
  const Result iso = run_cli({"edit", model, "-o", edited, "--isotropic"});
  ASSERT_EQ(iso.code, 0) << iso.err;
  EXPECT_EQ(nlohmann::json::parse(testing::read_file(edited))["interaction"][0]["axes"].size(), 1u);
  const std::string untouched = dir.file("u.json").string();
  expect_one_line_error(run_cli({"edit", model, "-o", untouched, "--gamma", "0:9:1=1"}), 2,
                        "axis '9'");
  expect_one_line_error(run_cli({"edit", model, "-o", untouched, "--gamma", "0:0:1=-1"}), 2,
                        "invalid");
  expect_one_line_error(run_cli({"edit", model, "-o", untouched, "--beta", "nobody=1"}), 2,
                        "category");
  expect_one_line_error(run_cli({"edit", model, "-o", untouched, "--threshold", "0:0=3"}), 2,
                        "PAIR:AXIS:INDEX");
  EXPECT_FALSE(std::filesystem::exists(untouched));
}

TEST(CliSynthesize, FitsThenSamples) {
  const testing::TempDir dir;
  const std::string out = dir.file("out.svg").string(), model = dir.file("m.json").string();
  const Result r = run_cli({"synthesize", data("svg/two-kinds.svg"), "--category-by", "fill",
                            "--quadrature", "8", "-o", out, "--model", model, "--size", "400,400",
                            "--seed", "4", "--iterations", "10000"});
  ASSERT_EQ(r.code, 0) << r.err;
  // One short summary of the fit, not the whole model.
  EXPECT_NE(r.out.find("fitted: 2D"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("pair 1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sampled"), std::string::npos);
  EXPECT_NE(testing::read_file(out).find("&quot;seed&quot;:4"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(model));
}

// A packed tile (tic-tac-toe: 4 elements per 64 x 64, fitted repeated 3 x 3; no finite
// pseudo-likelihood maximum): the chains start from the tile repeated over the output and keep its
// density; from the empty configuration they jam well below it (42 of 64 with this seed). A
// drawing the sampler mixes on (dots-random) starts empty unless asked. The record says which.
// The default start is empty, with the compressing burn-in (a crystal's growth) for a packed
// lattice tile (recorded); a chain that ends short of the exemplar's density says so with its
// count. `--start exemplar` starts from the tile repeated and says that the output begins as a
// copy.
TEST(CliSynthesize, StartsEmptyUnlessTheExemplarIsAskedFor) {
  const testing::TempDir dir;
  const std::string tile = data("third-party/hero-patterns/tic-tac-toe.svg");
  const auto run = [&](const std::string& name, std::vector<std::string> extra) {
    const std::string out = dir.file(name).string();
    std::vector<std::string> args = {"synthesize", tile,      "--tile", "-o", out,
                                     "--size",     "128,128", "--seed", "3"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run_cli(args);
    EXPECT_EQ(r.code, 0) << r.err;
    const Result stats = run_cli({"stats", out, "--json"});
    EXPECT_EQ(stats.code, 0) << stats.err;
    return std::make_tuple(testing::read_file(out),
                           nlohmann::json::parse(stats.out).at("elements").get<int>(), r.out);
  };
  const auto [sought, sought_count, sought_said] = run("sought.svg", {});
  EXPECT_NE(sought.find("[&quot;start&quot;,&quot;empty&quot;]"), std::string::npos);
  // tic-tac-toe is a lattice: its burn-in grows it as a crystal, and half its births at the
  // model are proposed near a neighbour (the fit's automatic share), which the record says.
  EXPECT_NE(sought.find("[&quot;burn_in&quot;,&quot;crystal&quot;]"), std::string::npos);
  EXPECT_NE(sought.find("[&quot;near_birth_share&quot;,&quot;0.5&quot;]"), std::string::npos);
  EXPECT_GT(sought_count, 0);
  EXPECT_EQ(sought_said.find("warning: the chain reached ") != std::string::npos,
            synthesis::falls_short(sought_count, 16))
      << sought_said;
  const auto [held, held_count, held_said] = run("held.svg", {"--start", "exemplar"});
  EXPECT_NE(held.find("[&quot;start&quot;,&quot;exemplar&quot;]"), std::string::npos);
  EXPECT_NE(held_said.find("start: the exemplar tiled over the output (16 elements)"),
            std::string::npos)
      << held_said;
  EXPECT_GE(held_count, 12);
  for (const auto& [start, expected] :
       {std::pair<std::string, std::string>{"auto", "empty"}, {"exemplar", "exemplar"}}) {
    const std::string out = dir.file("dots-" + start + ".svg").string();
    const Result r = run_cli({"synthesize", data("svg/dots-random.svg"), "--quadrature", "8", "-o",
                              out, "--size", "300,300", "--iterations", "2000", "--start", start});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(testing::read_file(out).find("[&quot;start&quot;,&quot;" + expected + "&quot;]"),
              std::string::npos)
        << start;
    EXPECT_EQ(r.out.find("start elements kept") != std::string::npos, expected == "exemplar")
        << r.out;
  }
  expect_one_line_error(run_cli({"synthesize", tile, "-o", dir.file("x.svg").string(), "--size",
                                 "100,100", "--start", "somewhere"}),
                        2, "--start");
  expect_one_line_error(
      run_cli({"synthesize", tile, "--method", "hybrid", "-o", dir.file("x.svg").string(), "--size",
               "100,100", "--start", "empty"}),
      2, "--start is for --method shape-process");
}

// A tile whose interactions reach further than half the side of its default 3 x 3 repeat (two
// dots 30 apart on a 60 x 12 strip: pairs 26 apart along x, the repeat 36 high) is fitted again
// on a repeat that holds them (2 (26 + 2 · 2.8) / 12 -> 6 x 6), says so, records it, and its
// output keeps every element of the repeated tile.
TEST(CliFit, ATileIsRefittedOnARepeatThatHoldsItsInteractions) {
  const testing::TempDir dir;
  const std::string tile = dir.write("strip.svg",
                                     "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"60\" "
                                     "height=\"12\" viewBox=\"0 0 60 12\"><circle cx=\"10\" "
                                     "cy=\"6\" r=\"2\"/><circle cx=\"40\" cy=\"6\" "
                                     "r=\"2\"/></svg>")
                               .string();
  const std::string model = dir.file("strip.json").string();
  const Result fit = run_cli({"fit", tile, "--tile", "-o", model});
  ASSERT_EQ(fit.code, 0) << fit.err;
  EXPECT_NE(fit.out.find("note: fitted on the tile repeated 6 x 6"), std::string::npos) << fit.out;
  const nlohmann::json record = nlohmann::json::parse(testing::read_file(model)).at("fit");
  EXPECT_EQ(record.at("tile_repeats"), 6);
  const std::string out = dir.file("strip-out.svg").string();
  // From empty the strip's jammed rows (dots at the hard core along both axes) are not reached
  // whole; the output says how far it got.
  const Result synthesised =
      run_cli({"sample", model, "-o", out, "--size", "240,48", "--seed", "1", "--quiet"});
  ASSERT_EQ(synthesised.code, 0) << synthesised.err;
  const Result stats = run_cli({"stats", out, "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  const int count = nlohmann::json::parse(stats.out).at("elements").get<int>();
  EXPECT_GT(count, 8);
  EXPECT_LE(count, 32);
  EXPECT_EQ(synthesised.out.find("warning: the chain reached ") != std::string::npos,
            synthesis::falls_short(count, 32))
      << synthesised.out;
  // The compressing burn-in needs a few steps of its own: fewer are refused, saying why.
  expect_one_line_error(run_cli({"sample", model, "-o", dir.file("few.svg").string(), "--size",
                                 "240,48", "--iterations", "3"}),
                        2, "--iterations: this model's outputs start with the compressing burn-in");
  // An output torus under twice the reach (range 57, dots 4 wide: 2 (57 + 4) = 123) is said to
  // be one (`sample` and `synthesize` share the check; the fitted model spares a fit per run).
  const Result small =
      run_cli({"sample", model, "-o", out, "--size", "60,60", "--iterations", "100", "--force"});
  ASSERT_EQ(small.code, 0) << small.err;
  EXPECT_NE(small.out.find("warning: the output torus is smaller than twice the model's reach"),
            std::string::npos)
      << small.out;
  const Result large =
      run_cli({"sample", model, "-o", out, "--size", "180,180", "--iterations", "100", "--force"});
  ASSERT_EQ(large.code, 0) << large.err;
  EXPECT_EQ(large.out.find("warning: the output torus"), std::string::npos) << large.out;
}

// -o naming a directory is refused, saying so, and nothing is written into it.
TEST(CliErrors, AnOutputThatIsADirectoryIsRefused) {
  const testing::TempDir dir;
  const std::string folder = dir.path().string();
  const Result convert = run_cli({"convert", data("svg/dots-random.svg"), "-o", folder});
  EXPECT_EQ(convert.code, 2);
  EXPECT_NE(convert.err.find("is a directory"), std::string::npos) << convert.err;
  const Result synthesize =
      run_cli({"synthesize", data("svg/dots-random.svg"), "-o", folder, "--size", "2W,2H"});
  EXPECT_EQ(synthesize.code, 2);
  EXPECT_NE(synthesize.err.find("is a directory"), std::string::npos) << synthesize.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// Hostile text from the command line or a file is not echoed as it came: a bad value of 1 MB
// gives a bounded one-line error, and a category name holding a terminal escape sequence is
// printed with '?' for its control characters.
TEST(CliErrors, HugeValuesAndEscapeSequencesAreNotEchoedWhole) {
  const testing::TempDir dir;
  const Result huge =
      run_cli({"synthesize", data("svg/dots-random.svg"), "-o", dir.file("x.svg").string(),
               "--size", std::string(1'000'000, '9') + "x"});
  EXPECT_EQ(huge.code, 2);
  EXPECT_LT(huge.err.size(), 700u) << huge.err.size();
  EXPECT_NE(huge.err.find("more bytes)"), std::string::npos);
  EXPECT_EQ(huge.err.find('\n'), huge.err.size() - 1);
  const std::string svg = dir.write("escape.svg",
                                    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" "
                                    "height=\"10\"><circle class=\"\x1b[31mred\" cx=\"5\" "
                                    "cy=\"5\" r=\"2\"/></svg>")
                              .string();
  const Result info = run_cli({"info", svg, "--category-by", "class"});
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_EQ(info.out.find('\x1b'), std::string::npos);
  EXPECT_NE(info.out.find("?[31mred: 1"), std::string::npos) << info.out;
}

TEST(CliStats, TextJsonAndComparisons) {
  const testing::TempDir dir;
  const Result text = run_cli({"stats", data("svg/dots-random.svg")});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("30 elements"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("collisions  0 overlapping pairs"), std::string::npos) << text.out;

  // Against itself: every distance is 0.
  const Result self = run_cli(
      {"stats", data("svg/dots-random.svg"), "--against", data("svg/dots-random.svg"), "--json"});
  ASSERT_EQ(self.code, 0) << self.err;
  const nlohmann::json j = nlohmann::json::parse(self.out);
  EXPECT_EQ(j["elements"], 30);
  EXPECT_EQ(j["boundary"], "open");
  EXPECT_DOUBLE_EQ(j["all"]["w1"]["nearest"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["neighbourhood_distance"]["mean"].get<double>(), 0.0);
  EXPECT_EQ(j["axes"].size(), 4u);

  // A sampled output knows it lives on a torus.
  const std::string out = dir.file("out.svg").string();
  ASSERT_EQ(run_cli({"synthesize", data("svg/dots-random.svg"), "--quadrature", "8", "-o", out,
                     "--size", "300,300", "--seed", "2", "--iterations", "20000"})
                .code,
            0);
  const Result output = run_cli({"stats", out, "--against", data("svg/dots-random.svg"), "--json"});
  ASSERT_EQ(output.code, 0) << output.err;
  const nlohmann::json o = nlohmann::json::parse(output.out);
  EXPECT_EQ(o["boundary"], "torus");
  EXPECT_EQ(o["collisions"]["pairs"], 0);
  EXPECT_GT(o["all"]["w1"]["nearest"].get<double>(), 0.0);

  expect_one_line_error(run_cli({"stats", dir.file("none.svg").string()}), 2, "none.svg");
  expect_one_line_error(run_cli({"stats", data("svg/dots-random.svg"), "--edge", "sideways"}), 2,
                        "--edge");
  expect_one_line_error(
      run_cli({"stats", data("svg/dots-random.svg"), "--against", data("mesh/pebbles.obj")}), 2,
      "3D");
}

// Mean and spread of a PNG's grey levels: a blank picture has no spread.
double grey_spread(const std::filesystem::path& png) {
  const geometry::Raster r = io::read_grayscale_png(png);
  double sum = 0.0, squares = 0.0;
  for (const float v : r.values) {
    sum += v;
    squares += static_cast<double>(v) * v;
  }
  const double n = static_cast<double>(r.values.size());
  return std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n)));
}

TEST(CliReport, WritesParsableHtmlSvgAndPictures) {
  const testing::TempDir dir;
  const std::string out = dir.file("out.svg").string(), model = dir.file("m.json").string();
  ASSERT_EQ(run_cli({"synthesize", data("svg/two-kinds.svg"), "--category-by", "fill",
                     "--quadrature", "8", "-o", out, "--model", model, "--size", "300,300",
                     "--seed", "4", "--iterations", "20000"})
                .code,
            0);
  const std::filesystem::path report = dir.file("report");
  const Result r = run_cli({"report", data("svg/two-kinds.svg"), out, "--category-by", "fill",
                            "--model", model, "-o", report.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("0 colliding pairs"), std::string::npos) << r.out;

  pugi::xml_document html;
  const pugi::xml_parse_result parsed = html.load_file((report / "index.html").c_str());
  ASSERT_TRUE(parsed) << parsed.description();
  EXPECT_STREQ(html.document_element().name(), "html");
  int charts = 0;
  for (const pugi::xpath_node& n : html.select_nodes("//svg")) {
    ++charts;
    EXPECT_STREQ(n.node().attribute("xmlns").value(), "http://www.w3.org/2000/svg");
  }
  EXPECT_GE(charts, 3 + 4 + 1);  // G, pairs, g, four axes, the interaction function
  std::vector<std::string> images;
  for (const pugi::xpath_node& n : html.select_nodes("//img"))
    images.push_back(n.node().attribute("src").value());
  ASSERT_EQ(images, (std::vector<std::string>{"exemplar.png", "output-1.png"}));
  for (const std::string& image : images) EXPECT_GT(grey_spread(report / image), 0.05) << image;
  // Both pictures share one scale: the 300-wide output is 300 / 220 times the exemplar's width.
  const geometry::Raster exemplar = io::read_grayscale_png(report / "exemplar.png");
  const geometry::Raster output = io::read_grayscale_png(report / "output-1.png");
  EXPECT_NEAR(static_cast<double>(output.width) / exemplar.width, 300.0 / 220.0, 0.01);
  pugi::xml_document plot;
  ASSERT_TRUE(plot.load_file((report / "interaction.svg").c_str()));
  const nlohmann::json metrics = nlohmann::json::parse(testing::read_file(report / "metrics.json"));
  EXPECT_EQ(metrics["outputs"].size(), 1u);
  // The verdicts: a one-line summary first, on the page and in metrics.json.
  const std::string summary = metrics["outputs"][0]["summary"].get<std::string>();
  EXPECT_EQ(r.out.find(out + ": " + summary + "\n"), 0u) << r.out;
  EXPECT_TRUE(summary.rfind("passes all", 0) == 0 || summary.rfind("fails", 0) == 0) << summary;
  EXPECT_GE(metrics["outputs"][0]["verdicts"].size(), 6u);  // density (3), mix, overlaps, …
  EXPECT_TRUE(html.select_node("//h2[text()='Verdicts']"));
  // The maximum-likelihood fit's goodness of fit: a row per sufficient statistic.
  ASSERT_TRUE(html.select_node("//h2[text()='Goodness of fit']"));
  EXPECT_TRUE(html.select_node("//h3[text()='Simulation envelopes']"));
  EXPECT_TRUE(html.select_node("//td[text()='G, all directions']"));
  EXPECT_TRUE(html.select_node("//td[text()='elements red']") ||
              html.select_node("//td[starts-with(text(), 'elements ')]"));

  // A missing output: one line naming it, and no report.
  const std::filesystem::path other = dir.file("other");
  expect_one_line_error(run_cli({"report", data("svg/two-kinds.svg"),
                                 dir.file("missing.svg").string(), "-o", other.string()}),
                        2, "missing.svg");
  EXPECT_FALSE(std::filesystem::exists(other));
  expect_one_line_error(run_cli({"report", data("svg/two-kinds.svg"), out, "-o", out}), 2,
                        "not a directory");
}

}  // namespace
}  // namespace shapeproc::cli

namespace shapeproc::cli {
namespace {

TEST(CliMessages, MisspeltOptionsAreNamedWithTheClosestValidOne) {
  expect_one_line_error(
      run_cli({"sample", "m.json", "--sizee", "4,4", "-o", "x.svg"}), 2,
      "unknown option '--sizee' (did you mean --size?); see shapeproc sample --help");
  expect_one_line_error(run_cli({"info", data("svg/dots-random.svg"), "--categry-by", "fill"}), 2,
                        "did you mean --category-by?");
  // Range checks say what is wanted in a few words.
  expect_one_line_error(
      run_cli({"sample", "m.json", "--size", "4,4", "-o", "x.svg", "--iterations", "-5"}), 2,
      "--iterations: must be >= 0, got -5");
  expect_one_line_error(
      run_cli({"sample", "m.json", "--size", "4,4", "-o", "x.svg", "--png-scale", "0"}), 2,
      "--png-scale: must be > 0, got 0");
  // Far from every option: no guess.
  const Result far = run_cli({"info", data("svg/dots-random.svg"), "--zzzzzzzz"});
  expect_one_line_error(far, 2, "unknown option '--zzzzzzzz'");
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(CliMessages, ModelArgumentsThatAreNotModels) {
  const testing::TempDir dir;
  const std::string out = dir.file("x.svg").string();
  expect_one_line_error(
      run_cli({"sample", data("svg/dots-random.svg"), "--size", "4,4", "-o", out}), 2,
      "this is an exemplar, not a model; use shapeproc synthesize");
  const std::string json = dir.write("other.json", R"({"name": "not a model"})").string();
  expect_one_line_error(run_cli({"sample", json, "--size", "4,4", "-o", out}), 2,
                        "not a shapeproc model file");
  expect_one_line_error(
      run_cli({"sample", json, "--size", "4,4", "-o", dir.file("x.bmp").string()}), 2,
      ".svg, .obj, .ply, .csv or .png");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliSynthesize, OptionsAreCheckedBeforeTheFit) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string();
  // --size with one number: refused before the (slow) fit, so no model file is written.
  expect_one_line_error(run_cli({"synthesize", data("svg/two-kinds.svg"), "--size", "440",
                                 "--model", model, "-o", dir.file("x.svg").string()}),
                        2, "--size");
  expect_one_line_error(run_cli({"synthesize", data("svg/two-kinds.svg"), "--size", "440,440",
                                 "--model", model, "--domain", dir.file("missing.svg").string(),
                                 "--boundary", "open", "-o", dir.file("x.svg").string()}),
                        2, "missing.svg: no such file");
  expect_one_line_error(
      run_cli({"synthesize", data("svg/two-kinds.svg"), "--size", "440,440", "--model", model,
               "--trace", dir.file("t.txt").string(), "-o", dir.file("x.svg").string()}),
      2, "--trace");
  EXPECT_FALSE(std::filesystem::exists(model));
}

TEST(CliSample, OutputsCarryLayersARecordAndPicturesTheirSeed) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string();
  ASSERT_EQ(run_cli({"fit", data("svg/two-kinds.svg"), "--category-by", "fill", "--quadrature", "8",
                     "-o", model})
                .code,
            0);
  const std::string out = dir.file("out.svg").string(), png = dir.file("out.png").string();
  const Result r = run_cli({"sample", model, "-o", out, "--size", "200,200", "--seed", "12",
                            "--iterations", "4000", "--png", png, "--png-scale", "2", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  // Each category in its own Inkscape layer.
  pugi::xml_document svg;
  ASSERT_TRUE(svg.load_file(out.c_str()));
  int layers = 0;
  for (pugi::xml_node g : svg.document_element().children("g")) {
    EXPECT_STREQ(g.attribute("inkscape:groupmode").value(), "layer");
    for (pugi::xml_node e : g.children())
      EXPECT_STREQ(e.attribute("data-category").value(), g.attribute("inkscape:label").value());
    ++layers;
  }
  EXPECT_EQ(layers, 2);
  // The picture: 2 pixels per unit, and the seed and command in its text.
  const geometry::Raster picture = io::read_grayscale_png(png);
  EXPECT_EQ(picture.width, 400);
  const std::string bytes = testing::read_file(png);
  EXPECT_NE(bytes.find("seed 12"), std::string::npos);
  EXPECT_NE(bytes.find("shapeproc sample"), std::string::npos);
  // The output read back as a torus by stats --boundary auto (the record says so).
  const Result stats = run_cli({"stats", out, "--json"});
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_EQ(nlohmann::json::parse(stats.out)["boundary"], "torus");
  // -o out.png: a picture of the output alone.
  ASSERT_EQ(run_cli({"sample", model, "-o", dir.file("only.png").string(), "--size", "200,200",
                     "--iterations", "100", "--quiet"})
                .code,
            0);
  EXPECT_EQ(io::read_grayscale_png(dir.file("only.png")).width, 800);
}

}  // namespace
}  // namespace shapeproc::cli

namespace shapeproc::cli {
namespace {

TEST(CliFit, MaximumLikelihoodMatchesTheExemplarsCount) {
  const testing::TempDir dir;
  const std::string model = dir.file("m.json").string();
  const Result r = run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "16", "--estimator",
                            "mle", "--mle-steps", "40000", "-o", model, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json fit = nlohmann::json::parse(testing::read_file(model))["fit"];
  const nlohmann::json& e = fit["estimator"];
  EXPECT_EQ(e["method"], "mcmc-mle");
  EXPECT_TRUE(e["converged"].get<bool>());
  // Every expected statistic within the fit's tolerance in Monte Carlo standard errors, but where
  // the attraction prior holds log γ down (there the expectation stays below the observed count).
  const std::vector<int> penalised = e["penalised"].get<std::vector<int>>();
  for (std::size_t k = 0; k < e["z"].size(); ++k) {
    const double z = e["z"][k].get<double>();
    if (std::find(penalised.begin(), penalised.end(), static_cast<int>(k)) == penalised.end())
      EXPECT_LE(std::abs(z), e["tolerance"].get<double>()) << k;
    else
      EXPECT_GT(z, 0.0) << k;
  }
  EXPECT_EQ(e["observed"][0], 30.0);
  // Same seed, same model bytes (but for the timings).
  const std::string again = dir.file("again.json").string();
  ASSERT_EQ(run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "16", "--estimator", "mle",
                     "--mle-steps", "40000", "-o", again, "--quiet"})
                .code,
            0);
  nlohmann::json a = nlohmann::json::parse(testing::read_file(model)),
                 b = nlohmann::json::parse(testing::read_file(again));
  for (nlohmann::json* j : {&a, &b}) {
    (*j)["fit"]["calibration"].erase("seconds");
    (*j)["fit"].erase("seconds");
    (*j)["fit"]["estimator"].erase("seconds");
    (*j)["fit"].erase("arguments");
  }
  EXPECT_EQ(a, b);
  // Border correction: the chains hold the border band's elements; the count still matches.
  const std::string border = dir.file("b.json").string();
  ASSERT_EQ(run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "16", "--edge", "border",
                     "--mle-steps", "40000", "-o", border, "--quiet"})
                .code,
            0);
  const nlohmann::json b_estimator =
      nlohmann::json::parse(testing::read_file(border))["fit"]["estimator"];
  EXPECT_TRUE(b_estimator["converged"].get<bool>());
  EXPECT_LE(std::abs(b_estimator["z"][0].get<double>()), b_estimator["tolerance"].get<double>());
}

// The stationary window: the record says so, the window's count is matched, `fidelity` checks
// the model the way it was fitted, and the pseudo-likelihood alone refuses it.
TEST(CliFit, AStationaryWindowIsFittedAndCheckedAsAPieceOfALargerDrawing) {
  const testing::TempDir dir;
  const std::string model = dir.file("s.json").string();
  // The default for an open window that is not packed: its summary says so.
  const Result r = run_cli({"fit", data("svg/dots-random.svg"), "--quadrature", "16", "-o", model});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("window: stationary"), std::string::npos) << r.out;
  const nlohmann::json e = nlohmann::json::parse(testing::read_file(model))["fit"]["estimator"];
  EXPECT_EQ(e["window"], "stationary");
  EXPECT_TRUE(e["converged"].get<bool>());
  EXPECT_EQ(e["observed"][0], 30.0);
  EXPECT_LE(std::abs(e["z"][0].get<double>()), e["tolerance"].get<double>());
  const Result checked = run_cli({"fidelity", data("svg/dots-random.svg"), "--model", model,
                                  "--edge", "stationary", "--chains", "10", "--quiet"});
  ASSERT_EQ(checked.code, 0) << checked.err;
  EXPECT_NE(checked.out.find("own window, 10 chains"), std::string::npos) << checked.out;
  // A packed exemplar keeps its own window, and --edge none asks for it.
  for (const auto& [exemplar, edge] :
       {std::pair{"svg/crescents-grid.svg", "auto"}, std::pair{"svg/dots-random.svg", "none"}}) {
    const std::string own = dir.file(std::string("own-") + edge + ".json").string();
    ASSERT_EQ(run_cli({"fit", data(exemplar), "--quadrature", "16", "--mle-steps", "5000", "--edge",
                       edge, "-o", own, "--quiet"})
                  .code,
              0);
    EXPECT_EQ(nlohmann::json::parse(testing::read_file(own))["fit"]["estimator"]["window"], "own")
        << exemplar;
  }
  const Result refused = run_cli({"fit", data("svg/dots-random.svg"), "--edge", "stationary",
                                  "--estimator", "mpl", "-o", dir.file("m.json").string()});
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--edge stationary"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.json")));
}

TEST(CliCompare, EveryMethodOnOnePageWithVerdictsAndTimes) {
  const testing::TempDir dir;
  const std::filesystem::path page = dir.file("compare");
  const Result r = run_cli({"compare", data("svg/crescents-grid.svg"), "--methods", "davison,ijiri",
                            "--size", "400,400", "--seed", "2", "-o", page.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  // Progress per method, then each method's one-line verdict.
  EXPECT_NE(r.out.find("[1/2] davison\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[2/2] ijiri\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\ndavison: "), std::string::npos) << r.out;
  // Each output is written where `synthesize` would have put it, with its record.
  for (const char* method : {"davison", "ijiri"}) {
    const std::string svg = testing::read_file(page / (std::string(method) + ".svg"));
    EXPECT_NE(svg.find("&quot;seed&quot;:2"), std::string::npos) << method;
  }
  pugi::xml_document html;
  ASSERT_TRUE(html.load_file((page / "index.html").c_str()));
  std::vector<std::string> images;
  for (const pugi::xpath_node& n : html.select_nodes("//img"))
    images.push_back(n.node().attribute("src").value());
  ASSERT_EQ(images, (std::vector<std::string>{"exemplar.png", "output-1.png", "output-2.png"}));
  for (const std::string& image : images) EXPECT_GT(grey_spread(page / image), 0.05) << image;
  // All of them in one picture, side by side at the page's scale, with room for the captions.
  const geometry::Raster sheet = io::read_grayscale_png(page / "overview.png");
  const geometry::Raster first = io::read_grayscale_png(page / "output-1.png");
  EXPECT_GT(sheet.width, 2 * first.width + io::read_grayscale_png(page / "exemplar.png").width);
  EXPECT_GT(sheet.height, first.height);
  EXPECT_GT(grey_spread(page / "overview.png"), 0.05);
  // Nothing the page needs comes from the network.
  const std::string text = testing::read_file(page / "index.html");
  EXPECT_EQ(text.find("http://"), text.find("http://www.w3.org/"));
  EXPECT_EQ(text.find("https://"), std::string::npos);
  EXPECT_TRUE(html.select_node("//h2[text()='Verdicts']"));
  EXPECT_TRUE(html.select_node("//td[text()='davison']"));  // its time, among the timings
  const nlohmann::json metrics = nlohmann::json::parse(testing::read_file(page / "metrics.json"));
  ASSERT_EQ(metrics["outputs"].size(), 2u);

  expect_one_line_error(run_cli({"compare", data("svg/crescents-grid.svg"), "--methods",
                                 "davison,magic", "--size", "400,400", "-o", page.string()}),
                        2, "unknown method 'magic'");
  const std::filesystem::path none = dir.file("none");
  expect_one_line_error(run_cli({"compare", dir.file("missing.svg").string(), "--size", "400,400",
                                 "-o", none.string()}),
                        2, "missing.svg");
  EXPECT_FALSE(std::filesystem::exists(none));
}

}  // namespace
}  // namespace shapeproc::cli
