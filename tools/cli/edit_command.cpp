// shapeproc edit model.json -o new.json [--beta CAT=V] [--scale-beta F] [--gamma P:A:B=V]
// [--threshold P:A:I=V] [--scale-thresholds F] [--isotropic]: the paper's §7.3 edits.
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/model/model_edits.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

namespace {

struct EditArguments {
  std::string model, output;
  std::vector<std::string> beta, gamma, threshold;
  double scale_beta = 1.0, scale_thresholds = 1.0;
  bool isotropic = false;
};

double parse_value(const std::string& text, const std::string& option, const std::string& edit) {
  const auto values = io::parse_number_list(text);
  if (!values || values->size() != 1)
    throw core::UsageError(option + " " + edit + ": expected a number after '='");
  return values->front();
}

// "0", "2" or "*" (every index below `count`).
std::vector<std::size_t> parse_indices(const std::string& text, std::size_t count,
                                       std::size_t first, const std::string& what,
                                       const std::string& option, const std::string& edit) {
  if (text == "*") {
    std::vector<std::size_t> all;
    for (std::size_t i = first; i < count + first; ++i) all.push_back(i - first);
    return all;
  }
  const auto values = io::parse_number_list(text);
  if (!values || values->size() != 1 || values->front() != std::floor(values->front()) ||
      values->front() < static_cast<double>(first) ||
      values->front() >= static_cast<double>(count + first)) {
    std::ostringstream message;
    message << option << " " << edit << ": " << what << " '" << text << "' is not one of " << first
            << ".." << count + first - 1 << " or *";
    throw core::UsageError(message.str());
  }
  return {static_cast<std::size_t>(values->front()) - first};
}

// PAIR:AXIS:INDEX=VALUE, applied by `apply(pair, axis, index, value)` to every index it names.
template <class F>
void edit_axes(model::ShapeProcessModel& m, const std::string& edit, const std::string& option,
               const char* index_name, bool thresholds, F apply) {
  const auto equals = edit.find('=');
  std::vector<std::string> parts;
  std::stringstream fields(edit.substr(0, equals));
  for (std::string part; std::getline(fields, part, ':');) parts.push_back(part);
  if (equals == std::string::npos || parts.size() != 3) {
    throw core::UsageError(option + " " + edit + ": expected PAIR:AXIS:" + index_name +
                           "=VALUE (indices as in shapeproc show)");
  }
  const double value = parse_value(edit.substr(equals + 1), option, edit);
  for (std::size_t p : parse_indices(parts[0], m.interactions.size(), 0, "pair", option, edit)) {
    const auto& axes = m.interactions[p].axes;
    for (std::size_t a : parse_indices(parts[1], axes.size(), 0, "axis", option, edit)) {
      const std::size_t count = thresholds ? axes[a].thresholds.size() : axes[a].gammas.size();
      for (std::size_t k :
           parse_indices(parts[2], count, thresholds ? 0 : 1, index_name, option, edit))
        apply(p, a, k, value);
    }
  }
}

int run_edit(const EditArguments& args, const std::vector<std::string>& arguments,
             std::ostream& out) {
  if (io::extension_of(args.output) != "json")
    throw core::UsageError(args.output + ": the model is written as .json");
  model::ShapeProcessModel m = io::read_model(args.model);
  if (!(args.scale_beta > 0 && std::isfinite(args.scale_beta)))
    throw core::UsageError("--scale-beta must be positive");
  if (!(args.scale_thresholds > 0 && std::isfinite(args.scale_thresholds)))
    throw core::UsageError("--scale-thresholds must be positive");
  // The edits themselves are the library's (model/model_edits.hpp); this parses their options.
  std::vector<std::string> edits;
  if (args.isotropic) {
    model::make_isotropic(m);
    edits.push_back("isotropic");
  }
  if (args.scale_beta != 1.0) {
    model::scale_intensities(m, args.scale_beta);
    edits.push_back("scale-beta " + core::format_number(args.scale_beta));
  }
  if (args.scale_thresholds != 1.0) {
    model::scale_thresholds(m, args.scale_thresholds);
    edits.push_back("scale-thresholds " + core::format_number(args.scale_thresholds));
  }
  for (const std::string& edit : args.beta) {
    const auto equals = edit.find('=');
    if (equals == std::string::npos)
      throw core::UsageError("--beta " + edit + ": expected CATEGORY=VALUE");
    const std::string name = edit.substr(0, equals);
    const double value = parse_value(edit.substr(equals + 1), "--beta", edit);
    std::size_t index = m.categories.size();
    for (std::size_t c = 0; c < m.categories.size(); ++c)
      if (m.categories[c].name == name) index = c;
    if (index == m.categories.size())
      index = parse_indices(name, m.categories.size(), 0, "category", "--beta", edit).front();
    model::set_intensity(m, index, value);
    edits.push_back("beta " + edit);
  }
  for (const std::string& edit : args.gamma) {
    edit_axes(m, edit, "--gamma", "BAND", false,
              [&](std::size_t pair, std::size_t axis, std::size_t band, double value) {
                model::set_gamma(m, pair, axis, band, value);
              });
    edits.push_back("gamma " + edit);
  }
  for (const std::string& edit : args.threshold) {
    edit_axes(m, edit, "--threshold", "INDEX", true,
              [&](std::size_t pair, std::size_t axis, std::size_t index, double value) {
                model::set_threshold(m, pair, axis, index, value);
              });
    edits.push_back("threshold " + edit);
  }
  try {
    model::validate(m);
  } catch (const std::exception& e) {
    throw core::UsageError(std::string("the edited model is invalid: ") + e.what());
  }
  if (!m.fit) m.fit.emplace();
  m.fit->edits.push_back({args.model, arguments, edits});
  io::write_model(m, args.output);
  print_model_summary(m, out);
  out << "wrote " << args.output << '\n';
  return 0;
}

}  // namespace

void add_edit_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  auto args = std::make_shared<EditArguments>();
  CLI::App* command =
      app.add_subcommand("edit", "Edit a model's parameters (indices as in shapeproc show)");
  command->add_option("MODEL", args->model, "model file (.json)")->required();
  command->add_option("-o,--output", args->output, "edited model (.json)")->required();
  command->add_option("--beta", args->beta,
                      "set a category's beta: CATEGORY=VALUE (name or index); repeatable");
  command->add_option("--scale-beta", args->scale_beta, "multiply every beta by F");
  command->add_option("--gamma", args->gamma,
                      "set gamma: PAIR:AXIS:BAND=VALUE (band from 1; * for all); repeatable");
  command->add_option(
      "--threshold", args->threshold,
      "set a threshold: PAIR:AXIS:INDEX=VALUE (d0 is index 0; * for all); repeatable");
  command->add_option("--scale-thresholds", args->scale_thresholds,
                      "multiply every threshold by F");
  command->add_flag("--isotropic", args->isotropic, "average the axes into one (directions 1)");
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) { return run_edit(*args, arguments, out); };
  });
}

}  // namespace shapeproc::cli
