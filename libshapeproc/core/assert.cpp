#include "libshapeproc/core/assert.hpp"

namespace shapeproc::core::detail {

void fail_assertion(const char* file, int line, const char* condition, const std::string& message) {
  std::string what =
      std::string("internal error at ") + file + ":" + std::to_string(line) + ": " + condition;
  if (!message.empty()) what += " (" + message + ")";
  throw InternalError(what);
}

}  // namespace shapeproc::core::detail
