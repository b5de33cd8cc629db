#include "libshapeproc/io/synthesis_record_io.hpp"

#include <nlohmann/json.hpp>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"

namespace shapeproc::io {

namespace {

nlohmann::json pairs_json(const std::vector<std::pair<std::string, std::string>>& pairs) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [key, value] : pairs) out.push_back({key, value});
  return out;
}

std::vector<std::pair<std::string, std::string>> read_pairs(const nlohmann::json& list) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const nlohmann::json& item : list)
    out.emplace_back(item.at(0).get<std::string>(), item.at(1).get<std::string>());
  return out;
}

}  // namespace

Provenance synthesis_provenance(const synthesis::SynthesisRecord& r) {
  const nlohmann::json record = {{"method", r.method},
                                 {"seed", r.seed},
                                 {"chain", r.chain},
                                 {"chains", r.chains},
                                 {"chain_seed", r.chain_seed},
                                 {"boundary", geometry::to_string(r.boundary)},
                                 {"size", r.size},
                                 {"domain", r.domain_file},
                                 {"intensity", r.intensity_file},
                                 {"inputs", pairs_json(r.inputs)},
                                 {"options", pairs_json(r.options)},
                                 {"iterations", r.iterations},
                                 {"steps", r.steps},
                                 {"stationary", r.stationary}};
  const nlohmann::json provenance = {{"tool", "shapeproc"},
                                     {"version", SHAPEPROC_VERSION},
                                     {"command", r.command},
                                     {"arguments", r.arguments},
                                     {"synthesis", record}};
  return Provenance{provenance.dump()};
}

std::optional<synthesis::SynthesisRecord> parse_synthesis_record(const std::string& provenance,
                                                                 const std::string& source) {
  const nlohmann::json json = nlohmann::json::parse(provenance, nullptr, false);
  if (json.is_discarded() || !json.is_object() || !json.contains("synthesis")) return std::nullopt;
  try {
    const nlohmann::json& s = json.at("synthesis");
    synthesis::SynthesisRecord r;
    r.command = json.value("command", std::string());
    r.arguments = json.value("arguments", std::vector<std::string>());
    r.method = s.at("method").get<std::string>();
    r.seed = s.at("seed").get<std::uint64_t>();
    r.chain = s.at("chain").get<int>();
    r.chains = s.at("chains").get<int>();
    r.chain_seed = s.at("chain_seed").get<std::uint64_t>();
    r.boundary = geometry::parse_boundary(s.at("boundary").get<std::string>());
    r.size = s.at("size").get<std::vector<double>>();
    r.domain_file = s.value("domain", std::string());
    r.intensity_file = s.value("intensity", std::string());
    r.inputs = read_pairs(s.at("inputs"));
    r.options = read_pairs(s.at("options"));
    r.iterations = s.at("iterations").get<std::string>();
    r.steps = s.at("steps").get<long long>();
    r.stationary = s.at("stationary").get<bool>();
    return r;
  } catch (const std::exception& e) {
    throw core::InputError(source, 0, std::string("malformed synthesis record: ") + e.what());
  }
}

std::optional<synthesis::SynthesisRecord> read_synthesis_record(const std::filesystem::path& file) {
  const std::string text = read_provenance(file);
  if (text.empty()) return std::nullopt;
  return parse_synthesis_record(text, file.string());
}

}  // namespace shapeproc::io
