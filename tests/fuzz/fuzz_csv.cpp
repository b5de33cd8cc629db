// Fuzzes the CSV point reader: any bytes give a scene or an InputError or UsageError. The first
// byte picks whether a window is given (a CSV needs one).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/csv_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shapeproc;
  if (size == 0) return 0;
  io::ReaderOptions options;
  if ((data[0] & 1) != 0) options.window = io::WindowOption::parse("0,100,0,100");
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    io::parse_csv_points(text, "fuzz.csv", options);
  } catch (const core::InputError&) {
  } catch (const core::UsageError&) {
  }
  return 0;
}
