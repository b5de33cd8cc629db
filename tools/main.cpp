// shapeproc: statistical discrete-element texture synthesis from the command line.
#include <iostream>

#include "tools/cli/cli.hpp"

int main(int argc, char** argv) { return shapeproc::cli::run(argc, argv, std::cout, std::cerr); }
