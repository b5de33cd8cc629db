#include "libshapeproc/synthesis/synthesis_record.hpp"

#include <sstream>

namespace shapeproc::synthesis {

void SynthesisRecord::set_domain(const geometry::Domain& domain) {
  boundary = domain.boundary();
  size.clear();
  for (int axis = 0; axis < domain.dimension(); ++axis) size.push_back(domain.sizes()[axis]);
}

void SynthesisRecord::take_run(const SynthesisRecord& run) {
  method = run.method;
  boundary = run.boundary;
  size = run.size;
  if (domain_file.empty()) domain_file = run.domain_file;
  if (intensity_file.empty()) intensity_file = run.intensity_file;
  options.insert(options.end(), run.options.begin(), run.options.end());
  iterations = run.iterations;
  steps = run.steps;
  stationary = run.stationary;
}

namespace {
std::string find(const std::vector<std::pair<std::string, std::string>>& list,
                 const std::string& key) {
  for (const auto& [k, v] : list)
    if (k == key) return v;
  return {};
}
}  // namespace

std::string SynthesisRecord::option(const std::string& key) const { return find(options, key); }
std::string SynthesisRecord::input(const std::string& key) const { return find(inputs, key); }

std::string SynthesisRecord::summary() const {
  std::ostringstream s;
  s << "shapeproc " << (command.empty() ? "?" : command) << ", " << method << ", seed " << seed;
  if (chains > 1) s << ", chain " << chain;
  s << ", " << steps << " steps";
  if (iterations == "stationary") s << " (until stationary)";
  s << ", " << geometry::to_string(boundary);
  if (!domain_file.empty()) s << ", domain " << domain_file;
  if (!intensity_file.empty()) s << ", intensity map " << intensity_file;
  return s.str();
}

}  // namespace shapeproc::synthesis
