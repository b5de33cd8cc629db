// shapeproc studio EXEMPLAR|MODEL [--port N] [--size W,H] [--seed S] [--export-dir DIR]: a local
// page where a person edits a model and watches the pattern change (studio/).
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/interruption.hpp"
#include "libshapeproc/fit/fit_estimate.hpp"
#include "libshapeproc/io/domain_io.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/studio/studio_server.hpp"
#include "libshapeproc/studio/studio_session.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/flags.hpp"

namespace shapeproc::cli {

namespace {

struct StudioArguments {
  std::string input, size = "4W,4H", host = "127.0.0.1", export_dir = ".";
  int port = 0;
  std::uint64_t seed = 1;
  double final_seconds = 5.0;
  FitFlags fit;
  ReaderFlags reader;
  BudgetFlags budget;
};

// The preview's and the full output's sizes: twice and `size` times (4W,4H by default) the
// exemplar's window; for a model, its fit's window, or else half and all of --size.
void set_sizes(const StudioArguments& args, const std::optional<geometry::Box3>& window,
               studio::StudioInput& input) {
  const auto full = io::parse_size(args.size, window ? &*window : nullptr);
  if (!full || full->size() != 2 || !((*full)[0] > 0) || !((*full)[1] > 0) ||
      !std::isfinite((*full)[0]) || !std::isfinite((*full)[1]))
    throw core::UsageError("--size: expected W,H (positive)" +
                           std::string(window ? ", or multiples of the window such as 4W,4H"
                                              : " in the model's units (it records no window)") +
                           ", got '" + args.size + "'");
  input.full_size = *full;
  if (window) {
    const geometry::Vec3 sides = window->sizes();
    input.preview_size = {2 * sides.x(), 2 * sides.y()};
  } else {
    input.preview_size = {(*full)[0] / 2, (*full)[1] / 2};
  }
}

std::optional<geometry::Box3> recorded_window(const model::ShapeProcessModel& m) {
  if (!m.fit || m.fit->window_min.size() != 2 || m.fit->window_max.size() != 2) return std::nullopt;
  return geometry::Box3(geometry::Vec3(m.fit->window_min[0], m.fit->window_min[1], 0),
                        geometry::Vec3(m.fit->window_max[0], m.fit->window_max[1], 0));
}

studio::StudioInput read_input(const StudioArguments& args,
                               const std::vector<std::string>& arguments) {
  if (!std::filesystem::is_directory(args.export_dir))
    throw core::UsageError("--export-dir: " + args.export_dir + " is not a directory");
  studio::StudioInput input;
  input.source = args.input;
  input.arguments = arguments;
  input.seed = args.seed;
  input.final_seconds = args.final_seconds;
  input.export_directory = args.export_dir;
  if (io::extension_of(args.input) == "json") {
    input.model = io::read_model(args.input);
    if (input.model->dimension != 2)
      throw core::InputError(args.input, 0, "a 3D model: the studio draws its previews in 2D");
    set_sizes(args, recorded_window(*input.model), input);
    return input;
  }
  input.fit = args.fit.exemplar_options(args.reader);
  input.exemplar = io::read_scene(args.input, args.reader.options());
  if (input.exemplar->dimension != 2)
    throw core::InputError(args.input, 0, "a 3D exemplar: the studio draws its previews in 2D");
  core::check_budget(fit::estimate_fit(*input.exemplar, input.fit.fit).resources,
                     args.budget.budget(), "the fit of " + args.input,
                     "--quadrature, --directions or the thresholds");
  input.tile = args.reader.tile;
  const FitFlags flags = args.fit;
  const ReaderFlags reader = args.reader;
  const std::string file = args.input;
  input.record_fit = [flags, reader, file, arguments](model::ShapeProcessModel& m) {
    flags.record(m, file, reader, arguments);
  };
  set_sizes(args, input.exemplar->window, input);
  return input;
}

int run_studio(const StudioArguments& args, const std::vector<std::string>& arguments,
               std::ostream& out) {
  studio::StudioSession session(read_input(args, arguments));
  studio::ServerOptions options;
  options.host = args.host;
  options.port = args.port;
  studio::StudioServer server(session, options);
  out << "studio: open " << server.url() << '\n'
      << (session.state().phase == studio::Phase::fitting
              ? "fitting " + args.input + " (its progress shows on the page); "
              : std::string())
      << "exports go to " << std::filesystem::absolute(args.export_dir).string()
      << "; Ctrl-C stops the studio" << std::endl;
  // Ctrl-C: the section's flag is set, and the watcher stops the server (again until it has
  // stopped: a stop before the server runs would be lost).
  const core::CancellableSection interrupt;
  std::atomic<bool> served{false};
  std::thread watcher([&] {
    while (!served) {
      if (interrupt.flag()->load()) {
        session.close();  // wakes the requests that wait for a picture
        server.stop();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  server.run();
  served = true;
  watcher.join();
  out << "studio stopped\n";
  return 0;
}

}  // namespace

void add_studio_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  auto args = std::make_shared<StudioArguments>();
  CLI::App* command = app.add_subcommand(
      "studio", "Edit a model on a local page and watch its pattern change (docs/studio.md)");
  command->add_option("INPUT", args->input, "exemplar to fit (.svg, ...) or model (.json)")
      ->required();
  command->add_option("--port", args->port, "port to listen on (default: a free one)")
      ->check(CLI::Range(0, 65535));
  command
      ->add_option("--host", args->host,
                   "address to listen on (default 127.0.0.1: this machine only)")
      ->capture_default_str();
  command
      ->add_option("--size", args->size,
                   "the full size W,H, or multiples of the exemplar's window (previews are "
                   "2W,2H)")
      ->capture_default_str();
  command->add_option("--seed", args->seed, "the first seed")->capture_default_str();
  command
      ->add_option("--final-seconds", args->final_seconds,
                   "a final preview's chain still running this long after the edit is cut short "
                   "(the draft stays; export samples it in full)")
      ->check(positive_number())
      ->capture_default_str();
  command
      ->add_option("--export-dir", args->export_dir,
                   "directory exports are written to (the only place the studio writes)")
      ->capture_default_str();
  args->reader.add_to(*command);
  args->fit.add_to(*command);
  args->budget.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) { return run_studio(*args, arguments, out); };
  });
}

}  // namespace shapeproc::cli
