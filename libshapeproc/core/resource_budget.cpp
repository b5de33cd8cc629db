#include "libshapeproc/core/resource_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::core {

double ResourceBudget::default_memory() {
  const double cap = 16.0 * (1ull << 30);
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return cap;
  return std::min(cap, 0.75 * static_cast<double>(pages) * static_cast<double>(page));
}

std::string format_bytes(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 5) {
    bytes /= 1024.0;
    ++u;
  }
  return format_general(bytes, 3) + " " + units[u];
}

void check_budget(const ResourceEstimate& estimate, const ResourceBudget& budget,
                  const std::string& what, const std::string& lower) {
  if (!(estimate.elements <= budget.max_elements)) {
    const std::string count = std::isfinite(estimate.elements)
                                  ? "about " + format_general(estimate.elements, 3)
                                  : std::string("an unbounded number of");
    throw UsageError(what + " would hold " + count + " elements (" + estimate.basis +
                     "), more than {max_elements} " + format_general(budget.max_elements, 6) +
                     "; lower " + lower + " or raise {max_elements}");
  }
  if (!(estimate.bytes <= budget.max_memory)) {
    throw UsageError(what + " would need about " + format_bytes(estimate.bytes) + " of memory (" +
                     estimate.basis + "), more than {max_memory} " +
                     format_bytes(budget.max_memory) + "; lower " + lower +
                     " or raise {max_memory}");
  }
}

double parse_bytes(const std::string& text, const std::string& flag) {
  std::string number = text;
  double scale = 1.0;
  if (!number.empty()) {
    const char unit = static_cast<char>(std::toupper(static_cast<unsigned char>(number.back())));
    const std::string units = "KMGT";
    if (const auto at = units.find(unit); at != std::string::npos) {
      scale = std::pow(1024.0, static_cast<double>(at + 1));
      number.pop_back();
    }
  }
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value) ||
      value <= 0) {
    throw UsageError(flag + ": expected a positive size such as 8G or 512M, got '" +
                     printable(text, 60) + "'");
  }
  return value * scale;
}

}  // namespace shapeproc::core
