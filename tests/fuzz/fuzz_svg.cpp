// Fuzzes the SVG reader: any bytes give a scene or an InputError, never a crash, a hang or a
// balloon. The first byte picks the reader options, so that each way of reading is reached.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/svg_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shapeproc;
  if (size == 0) return 0;
  io::ReaderOptions options;
  const std::uint8_t pick = data[0];
  options.tile = (pick & 1) != 0;
  options.split_subpaths = (pick & 2) != 0;
  options.elements = (pick & 4) != 0 ? io::ElementRule::visual : io::ElementRule::automatic;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    io::parse_svg(text, "fuzz.svg", options);
  } catch (const core::InputError&) {
  } catch (const core::UsageError&) {
  }
  return 0;
}
