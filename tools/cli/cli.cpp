#include "tools/cli/cli.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>

#include "libshapeproc/core/error.hpp"
#include "tools/cli/commands.hpp"

namespace shapeproc::cli {

namespace {

// One line, whatever the exception carried.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
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
  add_fit_command(app, action, arguments);
  add_show_command(app, action);
  add_sample_command(app, action, arguments);
  add_synthesize_command(app, action, arguments);
  add_edit_command(app, action, arguments);
  add_stats_command(app, action);
  add_report_command(app, action, arguments);

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
    err << "shapeproc: " << one_line(e.what()) << " (see shapeproc --help)\n";
    return 2;
  }

  try {
    return action ? action(out) : 2;
  } catch (const core::InputError& e) {
    err << "shapeproc: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const core::UsageError& e) {
    err << "shapeproc: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const std::exception& e) {
    err << "shapeproc: internal error: " << one_line(e.what()) << '\n';
    return 1;
  }
}

}  // namespace shapeproc::cli
