// The `shapeproc` command line. Exit codes: 0 success, 2 bad input or options (one-line message
// naming the file), 1 internal failure.
#pragma once

#include <ostream>

namespace shapeproc::cli {

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace shapeproc::cli
