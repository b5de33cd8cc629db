// shapeproc show model.json [--plot interaction.svg]: the summary of a model, and its picture.
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/render/interaction_plot.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/model_summary.hpp"

namespace shapeproc::cli {

void add_show_command(CLI::App& app, Action& action) {
  struct ShowArguments {
    std::string model, plot;
  };
  auto args = std::make_shared<ShowArguments>();
  CLI::App* command = app.add_subcommand(
      "show", "Print a model's parameters; --plot draws its interaction function (SVG)");
  command->add_option("MODEL", args->model, "model file (.json)")->required();
  command->add_option("--plot", args->plot, "write the interaction plot (.svg)");
  command->callback([&action, args] {
    action = [args](std::ostream& out) {
      const model::ShapeProcessModel model = io::read_model(args->model);
      print_model_summary(model, out);
      if (!args->plot.empty()) {
        if (io::extension_of(args->plot) != "svg")
          throw core::UsageError(args->plot + ": the plot is written as .svg");
        render::write_interaction_plot(model, args->plot);
        out << "wrote " << args->plot << '\n';
      }
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
