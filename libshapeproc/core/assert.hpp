// SHAPEPROC_ASSERT(condition, message): the one macro for internal invariants. Unlike assert(),
// it is checked in every build type and throws core::InternalError naming the file and line, so
// a broken invariant is a clear failure rather than undefined behaviour.
#pragma once

#include <string>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::core::detail {
[[noreturn]] void fail_assertion(const char* file, int line, const char* condition,
                                 const std::string& message);
}  // namespace shapeproc::core::detail

#define SHAPEPROC_ASSERT(condition, message)                                                \
  do {                                                                                      \
    if (!(condition))                                                                       \
      ::shapeproc::core::detail::fail_assertion(__FILE__, __LINE__, #condition, (message)); \
  } while (false)
