// Pieces shared by the subcommands: reader options on the command line and provenance records.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "libshapeproc/core/resource_budget.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/reader_options.hpp"
#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::cli {

// --max-elements and --max-memory: the budget a command's estimate of its needs is checked
// against before any work (core/resource_budget.hpp).
struct BudgetFlags {
  double max_elements = core::ResourceBudget{}.max_elements;
  std::string max_memory;  // empty: the default

  void add_to(CLI::App& command);
  core::ResourceBudget budget() const;  // throws core::UsageError for a bad --max-memory
};

// Reader options as typed on the command line, turned into io::ReaderOptions after parsing.
struct ReaderFlags {
  std::string elements = "auto";
  std::string nested = "join";
  bool tile = false;
  bool split_subpaths = false;
  std::string groups = "element";
  std::string category_by = "none";
  std::string split = "components";
  std::string window;

  void add_to(CLI::App& command);
  io::ReaderOptions options() const;  // throws core::UsageError
  nlohmann::json to_json() const;
  // The flags as they would be typed again (for commands that run others: `compare`).
  std::vector<std::string> arguments() const;
  // The exemplar's window as the comparison methods take it: a --tile is one period of a torus,
  // anything else an open window.
  geometry::Boundary boundary() const {
    return tile ? geometry::Boundary::torus : geometry::Boundary::open;
  }
};

// The exemplar a fit learns from: the file as read, or, for a --tile of few elements, the tile
// repeated so that each element's periodic images are elements (geometry/tile_repeat.hpp).
struct FittingExemplar {
  geometry::Scene scene;
  int repeats = 1;  // along each side
};
// `repeats` 0: as many as geometry::tile_repeats gives for the tile's elements.
FittingExemplar read_fitting_exemplar(const std::string& input, const ReaderFlags& reader,
                                      int repeats = 0);

// The repeats a model's fit used for its tile (its record's `tile_repeats`), 0 when none is
// recorded.
int model_tile_repeats(const model::ShapeProcessModel& model);

// --distance shape|centroid|hausdorff and --direction gravitation|centroid, and their values.
void add_measurement_kind_options(CLI::App& command, std::string& distance, std::string& direction);
geometry::DistanceKind distance_kind(const std::string& name);
geometry::DirectionKind direction_kind(const std::string& name);

// Throws core::UsageError unless `file` ends in an extension scenes can be written to (.svg, .obj,
// .ply, .csv, or .png for a picture of the scene); `option` names the flag in the message.
void check_output_extension(const std::string& file, const std::string& option);

// Option checks with short messages ("must be > 0, got 0"), in place of CLI11's range validators
// whose messages print the largest double.
CLI::Validator positive_number();
CLI::Validator non_negative_number();

// The command line as a user would retype it: "shapeproc" and the arguments after the program.
std::string command_line(const std::vector<std::string>& arguments);

// Provenance of an output: tool, version, subcommand, the full argument list and parameters.
io::Provenance make_provenance(const std::string& command,
                               const std::vector<std::string>& arguments,
                               const nlohmann::json& parameters);

// An error message on one line, safe for a terminal and of bounded length: a bad value of 5 MB
// or one holding escape sequences is not echoed whole.
std::string one_line(std::string text);

// The flag of a library option named in an error message (core::name_options): "{window}" is
// --window, "{category_by}" --category-by, "{mesh_split}" --split.
std::string flag_for(std::string_view option);

}  // namespace shapeproc::cli
