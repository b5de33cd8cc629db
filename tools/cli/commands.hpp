// Registration of the subcommands. Each adds itself to the app and, when chosen, sets `action`
// to the work to do once parsing succeeded.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace shapeproc::cli {

using Action = std::function<int(std::ostream& out)>;

void add_info_command(CLI::App& app, Action& action);
void add_convert_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_fit_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_show_command(CLI::App& app, Action& action);
void add_sample_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_synthesize_command(CLI::App& app, Action& action,
                            const std::vector<std::string>& arguments);
void add_edit_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_stats_command(CLI::App& app, Action& action);
void add_report_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_compare_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_measure_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_studio_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);
void add_fidelity_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments);

}  // namespace shapeproc::cli
