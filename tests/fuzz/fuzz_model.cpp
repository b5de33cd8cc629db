// Fuzzes the model file reader: any bytes give a validated model or an InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shapeproc;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const model::ShapeProcessModel model = io::parse_model(text, "fuzz.json");
    io::model_to_json(model);  // what was accepted can be written back
  } catch (const core::InputError&) {
  }
  return 0;
}
