// shapeproc: statistical discrete-element texture synthesis from the command line.
#include <iostream>

#include "libshapeproc/core/interruption.hpp"
#include "tools/cli/cli.hpp"

int main(int argc, char** argv) {
  shapeproc::core::install_interrupt_handlers();
  return shapeproc::cli::run(argc, argv, std::cout, std::cerr);
}
