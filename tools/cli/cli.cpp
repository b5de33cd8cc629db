#include "tools/cli/cli.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

namespace {

// Levenshtein distance, for suggesting the option a user meant.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "unknown option '--sizee' (did you mean --size?)" for the first argument CLI11 did not expect.
std::string unknown_option_message(const CLI::App& command,
                                   const std::vector<std::string>& extras) {
  const std::string given = extras.empty() ? std::string() : extras.front();
  const std::string name = given.substr(0, given.find('='));
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& long_name : option->get_lnames()) {
      const std::string candidate = "--" + long_name;
      const std::size_t d = edit_distance(name, candidate);
      if (d < best_distance) {
        best_distance = d;
        best = candidate;
      }
    }
  }
  std::string text =
      (name.rfind("-", 0) == 0 ? "unknown option '" : "unexpected argument '") + name + "'";
  if (!best.empty() && name.rfind("-", 0) == 0 &&
      best_distance <= std::max<std::size_t>(2, name.size() / 3)) {
    text += " (did you mean " + best + "?)";
  }
  return text;
}

}  // namespace

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app(
      "shapeproc: learn how the elements of an exemplar are arranged and synthesise new "
      "arrangements (statistical discrete-element texture synthesis)",
      "shapeproc");
  app.set_version_flag("--version", std::string("shapeproc ") + SHAPEPROC_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);

  const std::vector<std::string> arguments(argv, argv + argc);
  Action action;
  add_info_command(app, action);
  add_convert_command(app, action, arguments);
  add_measure_command(app, action, arguments);
  add_fidelity_command(app, action, arguments);
  add_fit_command(app, action, arguments);
  add_show_command(app, action);
  add_sample_command(app, action, arguments);
  add_synthesize_command(app, action, arguments);
  add_edit_command(app, action, arguments);
  add_stats_command(app, action);
  add_report_command(app, action, arguments);
  add_compare_command(app, action, arguments);
  add_studio_command(app, action, arguments);

  // CLI11 only says "a subcommand is required" for a misspelt one: name it.
  const std::vector<CLI::App*> subcommands = app.get_subcommands({});
  const bool known =
      argc > 1 && std::any_of(subcommands.begin(), subcommands.end(),
                              [&](const CLI::App* sub) { return sub->get_name() == argv[1]; });
  if (argc > 1 && argv[1][0] != '-' && !known) {
    std::string names;
    for (const CLI::App* sub : subcommands) names += (names.empty() ? "" : ", ") + sub->get_name();
    err << "shapeproc: unknown subcommand '" << argv[1] << "' (expected one of: " << names << ")\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    const CLI::App* chosen = &app;
    for (const CLI::App* sub : app.get_subcommands()) chosen = sub;
    out << chosen->help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << '\n';
    return 0;
  } catch (const CLI::ParseError& e) {
    const CLI::App* chosen = &app;
    for (const CLI::App* sub : app.get_subcommands()) chosen = sub;
    const std::string name = chosen == &app ? "shapeproc" : "shapeproc " + chosen->get_name();
    // A misspelt option is the likeliest cause of any parse error it comes with ("--size is
    // required" after "--sizee"): name it first.
    const std::vector<std::string> extras = chosen->remaining();
    if (!extras.empty() &&
        (extras.front().rfind("-", 0) == 0 || dynamic_cast<const CLI::ExtrasError*>(&e))) {
      err << name << ": " << unknown_option_message(*chosen, extras) << "; see " << name
          << " --help\n";
      return 2;
    }
    err << "shapeproc: " << one_line(e.what()) << " (see " << name << " --help)\n";
    return 2;
  }

  try {
    return action ? action(out) : 2;
  } catch (const core::InputError& e) {
    err << "shapeproc: " << one_line(e.shown(flag_for)) << '\n';
    return 2;
  } catch (const core::UsageError& e) {
    err << "shapeproc: " << one_line(e.shown(flag_for)) << '\n';
    return 2;
  } catch (const core::ArgumentError& e) {
    err << "shapeproc: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const core::Cancelled&) {
    err << "shapeproc: cancelled; nothing was written\n";
    return 130;
  } catch (const std::exception& e) {
    err << "shapeproc: internal error: " << one_line(e.what()) << '\n';
    return 1;
  }
}

}  // namespace shapeproc::cli
