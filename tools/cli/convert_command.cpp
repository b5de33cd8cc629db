// shapeproc convert EXEMPLAR -o OUT: read any supported scene, write it in the format of OUT.
#include <memory>

#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/render/raster.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

namespace {
struct ConvertArguments {
  std::string input;
  std::string output;
  ReaderFlags reader;
  double png_scale = 0.0;
};
}  // namespace

void add_convert_command(CLI::App& app, Action& action, const std::vector<std::string>& arguments) {
  auto args = std::make_shared<ConvertArguments>();
  CLI::App* command = app.add_subcommand(
      "convert",
      "Read an exemplar (SVG, OBJ, PLY, OFF, STL, CSV) and write it as SVG, OBJ, PLY, "
      "CSV or a PNG picture, chosen by the extension of -o");
  command->add_option("EXEMPLAR", args->input, "input file")->required();
  command->add_option("-o,--output", args->output, "output file (.svg, .obj, .ply, .csv, .png)")
      ->required();
  command
      ->add_option("--png-scale", args->png_scale,
                   "pixels per unit length of a PNG (default: 800 pixels along the longer side)")
      ->check(positive_number());
  args->reader.add_to(*command);
  command->callback([&action, args, arguments] {
    action = [args, arguments](std::ostream& out) {
      check_output_extension(args->output, "-o");
      const io::ReaderOptions options = args->reader.options();
      const geometry::Scene scene = io::read_scene(args->input, options);
      nlohmann::json parameters = {
          {"input", args->input}, {"output", args->output}, {"reader", args->reader.to_json()}};
      if (io::extension_of(args->output) == "png") {
        render::RenderOptions picture;
        picture.scale = args->png_scale;
        picture.text = {{"Software", std::string("shapeproc ") + SHAPEPROC_VERSION},
                        {"Source", "shapeproc convert " + args->input}};
        render::write_png(scene, args->output, picture);
      } else {
        io::write_scene(scene, args->output, make_provenance("convert", arguments, parameters));
      }
      out << "wrote " << args->output << ": " << scene.elements.size() << " elements, "
          << scene.categories.size() << " categories\n";
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
