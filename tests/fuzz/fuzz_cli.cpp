// Fuzzes the command line's parsing: the input's lines are the arguments. Whatever they are,
// the command ends with exit 0 or 2 (1 means a bug: an internal error) and one line of error.
// Run in an empty directory: no argument can name an existing input, so no command gets to work.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "tools/cli/cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = {"shapeproc"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 24; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\n') {
      args.push_back(current);
      current.clear();
    } else if (c != '\0') {
      current.push_back(c);
    }
  }
  if (!current.empty()) args.push_back(current);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = shapeproc::cli::run(static_cast<int>(argv.size()), argv.data(), out, err);
  if (code == 1) {
    std::fprintf(stderr, "exit 1 (a bug): %s", err.str().c_str());
    std::abort();
  }
  return 0;
}
