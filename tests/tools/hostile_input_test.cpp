// The catalogue of bad and extreme inputs (docs/reliability.md): each is given to the command line
// as a user would, and must end with one line naming what is wrong, exit 2, and nothing written.
// SHAPEPROC_CATALOGUE=1 prints the table of docs/reliability.md from the messages actually given.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "tests/tools/cli_test_support.hpp"

namespace shapeproc::cli {
namespace {

namespace fs = std::filesystem;

// A file of the case: its name and how to make its contents ("<dir>": a directory; "<zero>": a
// link to /dev/zero, a file without end).
struct CaseFile {
  std::string name;
  std::function<std::string()> contents;
};

struct HostileCase {
  std::string name;   // test name
  std::string input;  // what it is, for the table
  std::vector<CaseFile> files;
  std::vector<std::string> args;  // "@" at the start of an argument: the case's directory
  std::string message;            // part of the expected error line
};

std::string repeat(const std::string& text, int times) {
  std::string out;
  out.reserve(text.size() * static_cast<std::size_t>(times));
  for (int i = 0; i < times; ++i) out += text;
  return out;
}

const char* kSvgHead = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)";

std::string svg(const std::string& body) { return kSvgHead + body + "</svg>"; }

// A small valid exemplar: five dots.
std::string dots() {
  return svg(
      R"(<circle cx="10" cy="10" r="3"/><circle cx="50" cy="20" r="3"/><circle cx="80" cy="60" r="3"/>)"
      R"(<circle cx="30" cy="70" r="3"/><circle cx="60" cy="85" r="3"/>)");
}

std::string model(const std::string& beta = "0.01", const std::string& extra = "") {
  return R"({"format": "shapeproc-model", "version": 1, "dimension": 2,
  "categories": [ { "name": "dots", "beta": )" +
         beta + R"( } ],
  "interaction": [ { "categories": [0, 0], "axes": [
      { "direction": [1, 0], "thresholds": [2, 5], "gammas": [0.5] } ] } ],
  "shapes": [ { "category": 0, "geometry": { "type": "paths", "parts": [ { "d": "M0 0h4v2h-4z" } ] } } ])" +
         extra + "}";
}

std::string tetrahedron_off() {
  return "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

CaseFile file(std::string name, std::string text) {
  return {std::move(name), [text = std::move(text)] { return text; }};
}

std::vector<HostileCase> svg_cases() {
  const std::vector<std::string> info = {"info", "@in.svg"};
  return {
      {"svg_empty", "an empty SVG", {file("in.svg", "")}, info, "the file is empty"},
      {"svg_malformed", "unclosed XML", {file("in.svg", "<svg><g></svg>")}, info, "malformed XML"},
      {"svg_not_svg",
       "an XML root other than <svg>",
       {file("in.svg", "<html/>")},
       info,
       "not <svg>"},
      {"svg_no_window",
       "no viewBox, size or window rectangle",
       {file("in.svg", R"(<svg xmlns="http://www.w3.org/2000/svg"><circle r="1"/></svg>)")},
       info,
       "no window"},
      {"svg_bad_viewbox",
       "a viewBox of three numbers",
       {file("in.svg", R"(<svg viewBox="0 0 10"><circle r="1"/></svg>)")},
       info,
       "viewBox"},
      {"svg_zero_window",
       "a window of zero size",
       {file("in.svg", R"(<svg viewBox="0 0 0 0"><circle r="1"/></svg>)")},
       info,
       "zero size"},
      {"svg_nothing_drawn",
       "only <defs>",
       {file("in.svg", svg(R"(<defs><circle r="1"/></defs>)"))},
       info,
       "no elements found"},
      {"svg_bad_path",
       "path data with a stray letter",
       {file("in.svg", svg(R"(<path d="M 0 0 L 5 X"/>)"))},
       info,
       "cannot parse path data"},
      {"svg_overflowing_number",
       "a coordinate of 1e999 in path data",
       {file("in.svg", svg(R"(<path d="M 0 0 L 1e999 5 L 5 5 z"/>)"))},
       info,
       "cannot parse path data"},
      {"svg_huge_coordinate",
       "a circle at 1e308",
       {file("in.svg", svg(R"(<circle cx="1e308" cy="5" r="1"/>)"))},
       info,
       "beyond ±1e12"},
      {"svg_transform_overflow",
       "a transform that overflows to infinity",
       {file("in.svg",
             svg(R"x(<g transform="scale(1e300)"><circle cx="1e10" cy="1" r="1"/></g>)x"))},
       info,
       "not finite after transforms"},
      {"svg_bad_transform",
       "transform=\"rotate(x)\"",
       {file("in.svg", svg(R"x(<circle transform="rotate(x)" r="1"/>)x"))},
       info,
       "transform"},
      {"svg_negative_radius",
       "a circle of radius -1",
       {file("in.svg", svg(R"(<circle r="-1"/>)"))},
       info,
       "must not be negative"},
      {"svg_deep_groups",
       "groups nested 100,000 deep (a stack overflow before)",
       {{"in.svg",
         [] {
           return svg(repeat("<g>", 100000) + R"(<circle r="1"/>)" + repeat("</g>", 100000));
         }}},
       info,
       "nest more than 256 levels"},
      {"svg_use_doubling",
       "<use> doubling 24 times (\"billion laughs\")",
       {{"in.svg",
         [] {
           std::string body = R"(<defs><circle id="g0" r="1"/>)";
           for (int i = 1; i <= 24; ++i) {
             body += "<g id=\"g" + std::to_string(i) + "\"><use href=\"#g" + std::to_string(i - 1) +
                     "\"/><use href=\"#g" + std::to_string(i - 1) + "\"/></g>";
           }
           return svg(body + R"(</defs><use href="#g24"/>)");
         }}},
       info,
       "<use> makes more than 100000 copies"},
      {"svg_use_cycle",
       "a <use> that refers to itself",
       {file("in.svg", svg(R"(<g id="a"><use href="#a"/></g>)"))},
       info,
       "nest too deep"},
      {"svg_use_unknown",
       "a <use> of an unknown id",
       {file("in.svg", svg(R"(<use href="#nowhere"/>)"))},
       info,
       "unknown id"},
      {"svg_use_external",
       "a <use> of another file",
       {file("in.svg", svg(R"(<use href="other.svg#a"/>)"))},
       info,
       "needs href=\"#id\""},
      {"svg_too_many_segments",
       "a path of 2,100,000 segments",
       {{"in.svg", [] { return svg("<path d=\"M0 0" + repeat(" l1 1", 2100000) + "\"/>"); }}},
       info,
       "more than"},
      {"svg_endless",
       "/dev/zero named .svg",
       {file("in.svg", "<zero>")},
       info,
       "larger than 512 MiB"},
      {"svg_directory",
       "a directory named .svg",
       {file("in.svg", "<dir>")},
       info,
       "is a directory"},
      {"svg_missing", "a file that does not exist", {}, info, "no such file"},
      {"unknown_format",
       "an exemplar with extension .txt",
       {file("in.txt", "x")},
       {"info", "@in.txt"},
       "unknown format"},
  };
}

std::vector<HostileCase> model_cases() {
  const std::vector<std::string> show = {"show", "@m.json"};
  return {
      {"model_empty", "an empty model file", {file("m.json", "")}, show, "the file is empty"},
      {"model_malformed",
       "truncated JSON",
       {file("m.json", "{\"format\": ")},
       show,
       "malformed JSON"},
      {"model_deep",
       "JSON nested 100,000 deep",
       {{"m.json", [] { return repeat("[", 100000) + repeat("]", 100000); }}},
       show,
       "nests more than 64 levels"},
      {"model_number_overflow",
       "β = 1e999999",
       {file("m.json", model("1e999999"))},
       show,
       "number overflow"},
      {"model_directions_huge",
       "measurement.directions 2e9 (bad_alloc before)",
       {file("m.json", model("0.01", R"(, "measurement": { "directions": 2000000000 })"))},
       show,
       "at most 720"},
      {"model_not_model",
       "JSON that is not a model",
       {file("m.json", "{}")},
       show,
       "not a shapeproc model file"},
      {"model_too_many_categories",
       "65,537 categories (wrapped an int before)",
       {{"m.json",
         [] {
           std::string categories;
           for (int i = 0; i < 65537; ++i)
             categories +=
                 std::string(i ? "," : "") + R"({"name":"c)" + std::to_string(i) + R"(","beta":1})";
           return R"({"format":"shapeproc-model","version":1,"dimension":2,"categories":[)" +
                  categories + R"(],"interaction":[],"shapes":[]})";
         }}},
       show,
       "at most 4096 categories"},
      {"model_dimension_wraps",
       "dimension 4294967298 (wraps to 2 as an int)",
       {file("m.json",
             [] {
               std::string m = model();
               m.replace(m.find("\"dimension\": 2"), 14, "\"dimension\": 4294967298");
               return m;
             }())},
       show,
       "dimension: expected an integer in the range of an int"},
      {"model_category_wraps",
       "a category index of 4294967296",
       {file("m.json",
             [] {
               std::string m = model();
               m.replace(m.find("\"categories\": [0, 0]"), 20, "\"categories\": [0, 4294967296]");
               return m;
             }())},
       show,
       "expected an integer in the range of an int"},
      {"model_negative_gamma",
       "γ = -1",
       {file("m.json",
             [] {
               std::string m = model();
               m.replace(m.find("[0.5]"), 5, "[-1]");
               return m;
             }())},
       show,
       "gammas[0]"},
      {"model_huge_beta",
       "β = 1e300, sampled",
       {file("m.json", model("1e300"))},
       {"sample", "@m.json", "--size", "100,100", "-o", "@out.svg"},
       "--max-elements"},
      {"model_is_exemplar",
       "an SVG given where a model is expected",
       {file("m.svg", dots())},
       {"sample", "@m.svg", "--size", "100,100", "-o", "@out.svg"},
       "not a model"},
      {"studio_missing_export_dir",
       "studio with an export directory that does not exist",
       {file("m.json", model())},
       {"studio", "@m.json", "--size", "100,100", "--export-dir", "@missing"},
       "is not a directory"},
      {"studio_no_window",
       "studio on a model without a window, --size in multiples",
       {file("m.json", model())},
       {"studio", "@m.json", "--export-dir", "@"},
       "--size"},
      {"studio_bad_size",
       "studio with --size -5,10",
       {file("m.json", model())},
       {"studio", "@m.json", "--size", "-5,10", "--export-dir", "@"},
       "--size"},
  };
}

std::vector<HostileCase> table_and_mesh_cases() {
  const std::vector<std::string> csv = {"info", "@in.csv", "--window", "0,100,0,100"};
  return {
      {"csv_empty", "an empty CSV", {file("in.csv", "")}, csv, "empty"},
      {"csv_bad_number",
       "a coordinate 'abc'",
       {file("in.csv", "x,y\n1,2\nabc,3\n")},
       csv,
       "in.csv:3"},
      {"csv_infinite",
       "a coordinate 1e999",
       {file("in.csv", "x,y\n1,2\n1e999,3\n")},
       csv,
       "in.csv:3"},
      {"csv_no_window",
       "a CSV without --window",
       {file("in.csv", "x,y\n1,2\n")},
       {"info", "@in.csv"},
       "--window"},
      {"csv_5000_categories",
       "5,000 categories given to fit (ran until killed)",
       {{"in.csv",
         [] {
           std::string rows = "x,y,category\n";
           for (int i = 0; i < 5000; ++i)
             rows += std::to_string(i % 100) + "." + std::to_string(i / 100) + "," +
                     std::to_string(i / 50) + ",c" + std::to_string(i) + "\n";
           return rows;
         }}},
       {"fit", "@in.csv", "--window", "0,100,0,100", "-o", "@m.json"},
       "parameters"},
      {"off_huge_count",
       "an OFF header declaring 10^9 vertices (allocated 64 GB)",
       {file("in.off", "OFF\n1000000000 1 0\n0 0 0\n")},
       {"info", "@in.off"},
       "more than the file's"},
      {"off_negative_count",
       "an OFF header declaring -5 vertices",
       {file("in.off", "OFF\n-5 1 0\n")},
       {"info", "@in.off"},
       "from 0 to 2147483647"},
      {"off_garbage",
       "text that is not OFF",
       {file("in.off", "this is not a mesh\n")},
       {"info", "@in.off"},
       "not OFF"},
      {"off_infinite_vertex",
       "a vertex at 1e999",
       {file("in.off",
             [] {
               std::string t = tetrahedron_off();
               t.replace(t.find("1 0 0"), 5, "1e999 0 0");
               return t;
             }())},
       {"info", "@in.off"},
       "vertex 1 is not three finite numbers"},
      {"off_non_manifold",
       "three triangles on one edge",
       {file("in.off",
             "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n")},
       {"info", "@in.off"},
       "non-manifold"},
      {"off_control_characters",
       "OFF with NUL bytes and no line end (fuzzer: a 4.6 GB allocation)",
       {file("in.off", std::string("OFF 0 3 \0\0\0\0\0\v3 0 3 2 00 \0\v3 0 3 0 3 2", 31))},
       {"info", "@in.off"},
       "a control character (byte 0)"},
      {"off_counts_on_keyword_line",
       "OFF with its counts on the keyword's line",
       {file("in.off",
             "OFF 4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")},
       {"info", "@in.off"},
       "the counts must be on the line after OFF"},
      {"ply_bad_version",
       "a PLY format line of version '\\3761.0' (fuzzer: OpenMesh looped)",
       {file("in.ply",
             "ply\nformat binary_little_endian \3761.0\nelement vertex 4\nproperty float "
             "x\nproperty float y\nproperty float z\nelement face 4\nproperty list "
             "uchar int vertex_indices\nend_header\n" +
                 std::string(100, '\0'))},
       {"info", "@in.ply"},
       "unknown format line"},
      {"off_negative_corners",
       "an OFF face of -3 corners (fuzzer: a 3 GB allocation)",
       {file("in.off",
             "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n-03 0 1 3\n3 0 3 2\n3 1 2 3\n")},
       {"info", "@in.off"},
       "face 1 needs 3 to 1024 corners"},
      {"off_vertex_of_four_words",
       "an OFF vertex line of four words (fuzzer: shifted OpenMesh's reading, 2 GB)",
       {file("in.off", "OFF\n4 2 0\n4 4 0\n0 0 0\n0  0 2 ~\n3 01 1 3 2\n3 3 1 1 300000000000 3\n")},
       {"info", "@in.off"},
       "vertex 2 is not three finite numbers"},
      {"ply_negative_corners",
       "a PLY face of -3 corners (fuzzer: a 2 GB allocation)",
       {file("in.ply",
             "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float "
             "y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 1\n1 0 0\n0 1 0\n0 0 1\n-3 0 2 1\n")},
       {"info", "@in.ply"},
       "face 0: a list of -3 items"},
      {"ply_huge_count",
       "a PLY header declaring 10^9 vertices",
       {file("in.ply",
             "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nproperty float "
             "y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n")},
       {"info", "@in.ply"},
       "more than the file's"},
      {"ply_no_end",
       "a PLY header without end_header",
       {file("in.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n")},
       {"info", "@in.ply"},
       "no end_header"},
      {"ply_bad_type",
       "a PLY property of type 'quad'",
       {file("in.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n")},
       {"info", "@in.ply"},
       "bad property line"},
      {"obj_bad_index",
       "an OBJ face naming vertex 7 of 3",
       {file("in.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")},
       {"info", "@in.obj"},
       "names no vertex"},
      {"obj_endless_material",
       "an OBJ whose mtllib is /dev/zero",
       {file("in.obj", "mtllib zero.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n"),
        file("zero.mtl", "<zero>")},
       {"info", "@in.obj"},
       "mtllib"},
      {"stl_truncated",
       "a binary STL whose count does not match its size",
       {file("in.stl", std::string(80, ' ') + std::string("\x05\0\0\0", 4) + "xyz")},
       {"info", "@in.stl"},
       "binary STL"},
  };
}

std::vector<HostileCase> flag_cases() {
  const auto synth = [](std::vector<std::string> extra) {
    std::vector<std::string> args = {"synthesize", "@in.svg", "-o", "@out.svg"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::vector<CaseFile> exemplar = {file("in.svg", dots())};
  return {
      {"size_huge", "--size 1e9,1e9 (ran until killed)", exemplar, synth({"--size", "1e9,1e9"}),
       "--max-elements"},
      {"size_negative", "--size -5,5", exemplar, synth({"--size", "-5,5"}), "--size"},
      {"size_nan", "--size nan,5", exemplar, synth({"--size", "nan,5"}), "--size"},
      {"size_missing", "no --size", exemplar, synth({}), "--size is required"},
      {"iterations_huge", "--iterations 9000000000000000000", exemplar,
       synth({"--size", "100,100", "--iterations", "9000000000000000000"}),
       "--iterations: at most"},
      {"iterations_not_number", "--iterations 9e18 (not an integer)", exemplar,
       synth({"--size", "100,100", "--iterations", "9e18"}), "--iterations"},
      {"memory_budget", "--max-memory 1K", exemplar,
       synth({"--size", "100,100", "--max-memory", "1K"}), "more than --max-memory 1 KiB"},
      {"memory_budget_bad", "--max-memory lots", exemplar,
       synth({"--size", "100,100", "--max-memory", "lots"}), "--max-memory"},
      {"directions_huge",
       "fit --directions 2000000000 (bad_alloc before)",
       exemplar,
       {"fit", "@in.svg", "-o", "@m.json", "--directions", "2000000000"},
       "--max-memory"},
      {"measure_directions_huge",
       "measure --directions 2000000000 (bad_alloc before)",
       exemplar,
       {"measure", "@in.svg", "-o", "@pairs.csv", "--directions", "2000000000"},
       "at most 720"},
      {"size_multiple_unknown", "--size 3X,3H", exemplar, synth({"--size", "3X,3H"}),
       "multiples of the exemplar's window"},
      {"directions_odd",
       "fit --directions 3",
       exemplar,
       {"fit", "@in.svg", "-o", "@m.json", "--directions", "3"},
       "direction"},
      {"quadrature_huge",
       "fit --quadrature 100000 (ran until killed)",
       exemplar,
       {"fit", "@in.svg", "-o", "@m.json", "--quadrature", "100000"},
       "quadrature points"},
      {"quadrature_overflow",
       "fit --quadrature 1000000 (signed overflow before)",
       exemplar,
       {"fit", "@in.svg", "-o", "@m.json", "--quadrature", "1000000"},
       "quadrature points"},
      {"chains_zero", "--chains 0", exemplar, synth({"--size", "100,100", "--chains", "0"}),
       "--chains"},
      {"threads_huge", "--threads 100000", exemplar,
       synth({"--size", "100,100", "--threads", "100000"}), "--threads"},
      {"unknown_option", "a misspelt option", exemplar, synth({"--sizee", "100,100"}), "--sizee"},
      {"unknown_command",
       "a command that does not exist",
       {},
       {"synthesise-all"},
       "synthesise-all"},
      {"output_extension",
       "-o out.txt",
       exemplar,
       {"synthesize", "@in.svg", "-o", "@out.txt", "--size", "100,100"},
       "out.txt"},
      {"png_extension", "--png picture.jpg", exemplar,
       synth({"--size", "100,100", "--png", "@picture.jpg"}), "--png"},
      {"output_directory",
       "-o naming a directory",
       {file("in.svg", dots()), file("out", "<dir>")},
       {"convert", "@in.svg", "-o", "@out"},
       "out"},
      {"png_unwritable", "--png in a directory that cannot be made (the SVG was left behind)",
       exemplar, synth({"--size", "100,100", "--png", "/proc/none/picture.png"}),
       "cannot create the output file"},
      {"model_unwritable",
       "fit -o in a directory that cannot be made (found after the fit)",
       exemplar,
       {"fit", "@in.svg", "-o", "/proc/none/m.json"},
       "cannot create the output file"},
      {"seed_not_number", "--seed abc", exemplar, synth({"--size", "100,100", "--seed", "abc"}),
       "--seed"},
      {"huge_value", "a 1 MB option value", exemplar, synth({"--size", std::string(1 << 20, '9')}),
       "more bytes"},
  };
}

std::vector<HostileCase> all_cases() {
  std::vector<HostileCase> all;
  for (auto part : {svg_cases(), model_cases(), table_and_mesh_cases(), flag_cases()})
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

class HostileInput : public ::testing::TestWithParam<HostileCase> {};

TEST_P(HostileInput, OneLineExitTwoNothingWritten) {
  const HostileCase& c = GetParam();
  const testing::TempDir dir;
  std::set<fs::path> inputs;
  for (const CaseFile& f : c.files) {
    const fs::path path = dir.file(f.name);
    const std::string text = f.contents();
    if (text == "<dir>") {
      fs::create_directories(path);
    } else if (text == "<zero>") {
      fs::create_symlink("/dev/zero", path);
    } else {
      dir.write(f.name, text);
    }
    inputs.insert(path);
  }
  std::vector<std::string> args = c.args;
  for (std::string& a : args) {
    if (!a.empty() && a.front() == '@') a = (dir.path() / a.substr(1)).string();
  }
  const Result r = run_cli(args);
  expect_one_line_error(r, 2, c.message);
  for (const fs::directory_entry& e : fs::directory_iterator(dir.path()))
    EXPECT_TRUE(inputs.count(e.path())) << "left behind: " << e.path();
  if (std::getenv("SHAPEPROC_CATALOGUE")) {
    std::string line = r.err.substr(0, r.err.size() - 1);
    const std::string prefix = dir.path().string() + "/";
    for (std::size_t at; (at = line.find(prefix)) != std::string::npos;)
      line.erase(at, prefix.size());
    std::string input;
    for (const char ch : c.input) input += ch == '<' ? "&lt;" : std::string(1, ch);
    std::cout << "CATALOGUE| " << input << " | `" << line << "` | " << r.code << " |\n";
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, HostileInput, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<HostileCase>& param_info) {
                           return param_info.param.name;
                         });

}  // namespace
}  // namespace shapeproc::cli
