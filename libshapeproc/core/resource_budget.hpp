// Requests that would exhaust memory or run for hours are refused before any work starts: each
// command estimates what it will need (elements, bytes, work) and checks it against a budget that
// the user can raise.
#pragma once

#include <string>

namespace shapeproc::core {

struct ResourceBudget {
  double max_elements = 2e6;             // elements in one output (or one exemplar to fit)
  double max_memory = default_memory();  // bytes

  // 16 GiB, or three quarters of the machine's memory when it has less.
  static double default_memory();
};

// What a request is estimated to need, and how the estimate was made (for the refusal message).
struct ResourceEstimate {
  double elements = 0;
  double bytes = 0;
  std::string basis;  // e.g. "the exemplar's density times the domain's area"
};

// Throws UsageError naming `what`, the estimate, its basis, the limit and what to `lower` when
// the estimate exceeds the budget (or is not finite).
void check_budget(const ResourceEstimate& estimate, const ResourceBudget& budget,
                  const std::string& what, const std::string& lower);

// "12 GiB", "640 MiB": a byte count for messages.
std::string format_bytes(double bytes);

// Parses "8G", "512M", "2e9" (bytes; K, M, G, T are powers of 1024). Throws UsageError naming
// `flag`.
double parse_bytes(const std::string& text, const std::string& flag);

}  // namespace shapeproc::core
