// Exporting the studio's final preview: the edited model, the output `sample` makes from it, its
// picture and the command line.
#include <algorithm>
#include <cctype>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/render/raster.hpp"
#include "libshapeproc/studio/detail/session_shared.hpp"

namespace shapeproc::studio {

namespace {

void check_name(const std::string& name) {
  const bool plain = !name.empty() && name.size() <= 64 &&
                     std::all_of(name.begin(), name.end(), [](unsigned char c) {
                       return std::isalnum(c) || c == '-' || c == '_';
                     });
  if (!plain)
    throw core::ArgumentError("export",
                              "the name must be 1-64 letters, digits, '-' or '_' (it names the "
                              "files written)");
}

// `shapeproc sample NAME.json -o NAME.svg --size W,H --seed S`, word by word.
std::vector<std::string> sample_command(const std::string& name, const PreviewSpec& spec) {
  return {"shapeproc",
          "sample",
          name + ".json",
          "-o",
          name + ".svg",
          "--size",
          core::format_number(spec.size[0]) + "," + core::format_number(spec.size[1]),
          "--seed",
          std::to_string(spec.seed)};
}

std::string joined(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + word;
  return line;
}

}  // namespace

ExportResult StudioSession::export_preview(const std::string& name, bool overwrite) {
  check_name(name);
  Shared& s = *shared_;
  std::unique_lock<std::mutex> lock(s.mutex);
  if (!s.history) throw core::UsageError("the model is still being fitted");
  // The current revision's output: sampled by now, or soon.
  const long long wanted = s.revision;
  s.changed.wait(lock, [&] {
    return s.stopping || s.revision != wanted ||
           (s.final_output && s.final_output->revision == wanted) ||
           (s.latest && s.latest->revision == wanted && s.latest->stage != PreviewStage::draft);
  });
  if (s.stopping || s.revision != wanted)
    throw core::UsageError("the model changed while the export waited: export again");
  if (!s.final_output || s.final_output->revision != wanted)
    throw core::UsageError("the preview failed: " + (s.latest ? s.latest->note : std::string()));
  FinalOutput output = *s.final_output;
  lock.unlock();
  // A preview cut short at the time limit: its output, sampled in full now.
  if (!output.result) {
    synthesis::SynthesisRecord record;
    record.command = "sample";
    output.result = sample_output(output.model, output.spec, record, nullptr);
  }

  const std::filesystem::path dir = s.input.export_directory;
  ExportResult result;
  for (const char* extension : {".json", ".svg", ".png", ".sh"})
    result.files.push_back(dir / (name + extension));
  for (const auto& file : result.files) {
    if (!overwrite && std::filesystem::exists(file))
      throw core::ArgumentError("export", file.filename().string() +
                                              " exists in the export directory: give another "
                                              "name, or overwrite");
    core::check_writable(file);
  }
  synthesis::SynthesisRecord record = output.result->record;
  record.arguments = sample_command(name, output.spec);
  record.inputs = {{"model", name + ".json"}};
  result.command = joined(record.arguments);
  io::write_model(output.model, result.files[0]);
  io::write_scene(output.result->scene, result.files[1], io::synthesis_provenance(record));
  render::RenderOptions picture;
  picture.text = {{"Software", "shapeproc studio"},
                  {"Comment", "seed " + std::to_string(output.spec.seed)},
                  {"Source", result.command}};
  render::write_png(output.result->scene, result.files[2], picture);
  core::write_file_atomically(result.files[3], [&](std::ostream& out) {
    out << "#!/bin/sh\n# Makes " << name << ".svg from " << name
        << ".json, as the studio previewed it.\n"
        << result.command << '\n';
  });
  return result;
}

}  // namespace shapeproc::studio
