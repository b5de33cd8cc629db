// Fuzzes the mesh reader for one format (SHAPEPROC_FUZZ_EXTENSION): the header check and
// OpenMesh's reader behind it. The reader takes files, so each input is written to a file of this
// process first.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/mesh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shapeproc;
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("shapeproc-fuzz-" + std::to_string(getpid()) + "." SHAPEPROC_FUZZ_EXTENSION);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    io::read_mesh_scene(file, {});
  } catch (const core::InputError&) {
  } catch (const core::UsageError&) {
  }
  return 0;
}
