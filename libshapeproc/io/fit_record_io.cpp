#include "libshapeproc/io/fit_record_io.hpp"

#include <nlohmann/json.hpp>
#include <type_traits>

namespace shapeproc::io {

using nlohmann::json;

namespace {

json pairs_json(const std::vector<std::pair<std::string, std::string>>& pairs) {
  json out = json::array();
  for (const auto& [key, value] : pairs) out.push_back({key, value});
  return out;
}

json likelihood_json(const model::LikelihoodRecord& e) {
  return {{"method", "mcmc-mle"},
          {"window", e.stationary_window ? "stationary" : "own"},
          {"chains_start", "empty"},
          {"burn_in_kind", std::string(model::burn_in_name(e.burn_in_kind))},
          {"unbounded", e.unbounded},
          {"iterations", e.iterations},
          {"converged", e.converged},
          {"chains", e.chains},
          {"final_chains", e.final_chains},
          {"burn_in", e.burn_in},
          {"steps", e.steps},
          {"observe_every", e.observe_every},
          {"seed", e.seed},
          {"attraction_prior_sd", e.attraction_prior_sd},
          {"penalised", e.penalised},
          {"unreachable", e.unreachable},
          {"observed", e.observed},
          {"expected", e.expected},
          {"expected_standard_error", e.expected_standard_error},
          {"z", e.z},
          {"tolerance", e.tolerance},
          {"worst_r_hat", e.worst_r_hat},
          {"significance", e.significance},
          {"seconds", e.seconds}};
}

// `object[key]` as a T, or `fallback` when it is missing or of another type.
template <class T>
T field(const json& object, const char* key, T fallback) {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  // nlohmann converts between numbers and booleans freely: a count must be written as one.
  if constexpr (std::is_same_v<T, bool>) {
    if (!it->is_boolean()) return fallback;
  } else if constexpr (std::is_integral_v<T>) {
    if (!it->is_number_integer()) return fallback;
  } else if constexpr (std::is_arithmetic_v<T>) {
    if (!it->is_number()) return fallback;
  }
  try {
    return it->get<T>();
  } catch (const json::exception&) {
    return fallback;
  }
}

// Name and value pairs: a list of [name, value] (as written), or the objects of older files
// ({"tile": true} under "reader" is "reader.tile" = "true").
void read_options(const json& fit, std::vector<std::pair<std::string, std::string>>& out) {
  const auto text = [](const json& value) {
    return value.is_string() ? value.get<std::string>() : value.dump();
  };
  const auto it = fit.find("options");
  if (it != fit.end() && it->is_array()) {
    for (const json& item : *it)
      if (item.is_array() && item.size() == 2 && item[0].is_string())
        out.emplace_back(item[0].get<std::string>(), text(item[1]));
    return;
  }
  for (const char* group : {"reader", "options"}) {
    const auto g = fit.find(group);
    if (g == fit.end() || !g->is_object()) continue;
    const std::string prefix = std::string(group) == "reader" ? "reader." : "fit.";
    for (auto item = g->begin(); item != g->end(); ++item)
      out.emplace_back(prefix + item.key(), text(item.value()));
  }
}

model::LikelihoodRecord parse_likelihood(const json& e) {
  model::LikelihoodRecord r;
  r.stationary_window = field(e, "window", std::string()) == "stationary";
  const std::string burn_in = field(e, "burn_in_kind", std::string("plain"));
  const std::optional<model::BurnIn> kind = model::parse_burn_in(burn_in);
  if (!kind)
    throw std::invalid_argument("fit.likelihood.burn_in_kind: '" + burn_in +
                                "' is not plain, compressing or crystal");
  r.burn_in_kind = *kind;
  r.iterations = field(e, "iterations", 0);
  r.converged = field(e, "converged", false);
  r.chains = field(e, "chains", 0);
  r.final_chains = field(e, "final_chains", 0);
  r.burn_in = field(e, "burn_in", 0LL);
  r.steps = field(e, "steps", 0LL);
  r.observe_every = field(e, "observe_every", 0LL);
  r.seed = field(e, "seed", std::uint64_t{0});
  r.attraction_prior_sd = field(e, "attraction_prior_sd", 0.0);
  r.significance = field(e, "significance", 0.0);
  r.tolerance = field(e, "tolerance", 0.0);
  r.worst_r_hat = field(e, "worst_r_hat", 1.0);
  r.seconds = field(e, "seconds", 0.0);
  r.unbounded = field(e, "unbounded", std::vector<int>());
  r.penalised = field(e, "penalised", std::vector<int>());
  r.unreachable = field(e, "unreachable", std::vector<int>());
  r.observed = field(e, "observed", std::vector<double>());
  r.expected = field(e, "expected", std::vector<double>());
  r.expected_standard_error = field(e, "expected_standard_error", std::vector<double>());
  r.z = field(e, "z", std::vector<double>());
  return r;
}

json calibration_json(const model::CalibrationRecord& c) {
  return {{"multiple", c.multiple},
          {"rounds", c.rounds},
          {"converged", c.converged},
          {"ran_away", c.ran_away},
          {"ratio_before", c.ratio_before},
          {"ratio_after", c.ratio_after},
          {"beta_factor", c.beta_factor},
          {"attraction_shrink", c.attraction_shrink},
          {"seconds", c.seconds}};
}

model::CalibrationRecord parse_calibration(const json& c) {
  model::CalibrationRecord r;
  r.multiple = field(c, "multiple", r.multiple);
  r.rounds = field(c, "rounds", 0);
  r.converged = field(c, "converged", false);
  r.ran_away = field(c, "ran_away", false);
  r.ratio_before = field(c, "ratio_before", std::vector<double>());
  r.ratio_after = field(c, "ratio_after", std::vector<double>());
  r.beta_factor = field(c, "beta_factor", std::vector<double>());
  r.attraction_shrink = field(c, "attraction_shrink", 1.0);
  r.seconds = field(c, "seconds", 0.0);
  return r;
}

std::vector<model::ModelEdit> parse_edits(const json& fit) {
  std::vector<model::ModelEdit> edits;
  const auto it = fit.find("edits");
  if (it == fit.end() || !it->is_array()) return edits;
  for (const json& e : *it)
    edits.push_back({field(e, "from", std::string()),
                     field(e, "arguments", std::vector<std::string>()),
                     field(e, "edits", std::vector<std::string>())});
  return edits;
}

// The record's path, or for a file written before it had one, the path its estimator implies.
model::FitPath fit_path_of(const json& fit, const model::FitRecord& r) {
  if (const auto p = fit.find("path"); p != fit.end()) {
    const std::string name = p->is_string() ? p->get<std::string>() : p->dump();
    if (const std::optional<model::FitPath> path = model::parse_fit_path(name)) return *path;
    throw std::invalid_argument("fit.path: '" + name + "' is not a path the fit takes");
  }
  if (!r.likelihood) return model::FitPath::pseudo_likelihood;
  if (!r.likelihood->stationary_window) return model::FitPath::likelihood_own_window;
  const auto e = fit.find("estimator");
  return field(*e, "start", std::string()) == "mle of the window as drawn"
             ? model::FitPath::likelihood_stationary_restarted
             : model::FitPath::likelihood_stationary;
}

}  // namespace

json fit_record_json(const model::FitRecord& r) {
  const model::QuadratureRecord& q = r.quadrature;
  json fit = {
      {"window", {{"min", r.window_min}, {"max", r.window_max}}},
      {"elements", r.elements},
      {"edge", r.edge},
      {"path", model::fit_path_name(r.path)},
      {"quadrature",
       {{"method", q.lines ? "lines" : "cells"},
        {"cells", q.cells},
        {"cells_along_longest_side", q.cells_along_longest_side},
        {"shapes_per_location", q.shapes_per_location},
        {"refinement", q.refinement},
        {"points", q.points},
        {"data_weight", q.data_weight}}},
      {"data_points", r.data_points},
      {"log_pseudo_likelihood", r.log_pseudo_likelihood},
      {"optimiser",
       {{"method", r.optimiser}, {"evaluations", r.evaluations}, {"newton_steps", r.newton_steps}}},
      {"notes", r.notes},
      {"seconds",
       {{"proxies", r.seconds.proxies},
        {"measurements", r.seconds.measurements},
        {"quadrature", r.seconds.quadrature},
        {"optimisation", r.seconds.optimisation}}},
      {"version", r.version}};
  fit[r.thresholds.empty() ? "quantiles" : "thresholds"] =
      r.thresholds.empty() ? r.quantiles : r.thresholds;
  if (r.likelihood) fit["estimator"] = likelihood_json(*r.likelihood);
  if (r.calibration) fit["calibration"] = calibration_json(*r.calibration);
  if (!r.exemplar.empty()) fit["exemplar"] = r.exemplar;
  if (!r.arguments.empty()) fit["arguments"] = r.arguments;
  if (!r.options.empty()) fit["options"] = pairs_json(r.options);
  if (r.tile_repeats > 1) fit["tile_repeats"] = r.tile_repeats;
  if (!r.edits.empty()) {
    json edits = json::array();
    for (const model::ModelEdit& e : r.edits)
      edits.push_back({{"from", e.from}, {"arguments", e.arguments}, {"edits", e.edits}});
    fit["edits"] = edits;
  }
  return fit;
}

model::FitRecord parse_fit_record(const json& fit) {
  model::FitRecord r;
  if (!fit.is_object()) return r;
  if (const auto w = fit.find("window"); w != fit.end()) {
    r.window_min = field(*w, "min", std::vector<double>());
    r.window_max = field(*w, "max", std::vector<double>());
  }
  r.elements = field(fit, "elements", 0LL);
  r.edge = field(fit, "edge", std::string());
  r.quantiles = field(fit, "quantiles", std::vector<double>());
  r.thresholds = field(fit, "thresholds", std::vector<double>());
  if (const auto q = fit.find("quadrature"); q != fit.end()) {
    r.quadrature.lines = field(*q, "method", std::string()) == "lines";
    r.quadrature.cells = field(*q, "cells", 0LL);
    r.quadrature.cells_along_longest_side = field(*q, "cells_along_longest_side", 0);
    r.quadrature.shapes_per_location = field(*q, "shapes_per_location", 0);
    r.quadrature.refinement = field(*q, "refinement", 0);
    r.quadrature.points = field(*q, "points", 0LL);
    r.quadrature.data_weight = field(*q, "data_weight", 0.0);
  }
  r.data_points = field(fit, "data_points", 0LL);
  r.log_pseudo_likelihood = field(fit, "log_pseudo_likelihood", 0.0);
  if (const auto o = fit.find("optimiser"); o != fit.end()) {
    r.optimiser = field(*o, "method", std::string());
    r.evaluations = field(*o, "evaluations", 0);
    r.newton_steps = field(*o, "newton_steps", 0);
  }
  r.notes = field(fit, "notes", std::vector<std::string>());
  if (const auto s = fit.find("seconds"); s != fit.end()) {
    r.seconds = {field(*s, "proxies", 0.0), field(*s, "measurements", 0.0),
                 field(*s, "quadrature", 0.0), field(*s, "optimisation", 0.0)};
  }
  r.version = field(fit, "version", std::string());
  if (const auto e = fit.find("estimator");
      e != fit.end() && field(*e, "method", std::string()) == "mcmc-mle")
    r.likelihood = parse_likelihood(*e);
  if (const auto c = fit.find("calibration"); c != fit.end() && c->is_object())
    r.calibration = parse_calibration(*c);
  r.exemplar = field(fit, "exemplar", std::string());
  r.arguments = field(fit, "arguments", std::vector<std::string>());
  read_options(fit, r.options);
  r.tile_repeats = field(fit, "tile_repeats", 0);
  r.edits = parse_edits(fit);
  r.path = fit_path_of(fit, r);
  return r;
}

}  // namespace shapeproc::io
