#include "libshapeproc/studio/detail/studio_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::studio::detail {

namespace {

using nlohmann::json;

json parse_object(const std::string& body, const char* what) {
  json request = json::parse(body, nullptr, false);
  if (request.is_discarded() || !request.is_object())
    throw core::ArgumentError(what, "the request body must be a JSON object");
  return request;
}

const json& field(const json& request, const char* what, const char* name) {
  const auto it = request.find(name);
  if (it == request.end())
    throw core::ArgumentError(what, std::string("'") + name + "' is missing");
  return *it;
}

double number_field(const json& request, const char* what, const char* name) {
  const json& value = field(request, what, name);
  if (!value.is_number() || !std::isfinite(value.get<double>()))
    throw core::ArgumentError(what, std::string("'") + name + "' must be a finite number");
  return value.get<double>();
}

// A whole number >= 0 and below 2^53 (an index or a seed).
std::uint64_t whole_field(const json& request, const char* what, const char* name) {
  const json& value = field(request, what, name);
  const bool whole =
      value.is_number_unsigned() || (value.is_number() && value.get<double>() >= 0 &&
                                     value.get<double>() == std::floor(value.get<double>()) &&
                                     value.get<double>() < 9007199254740992.0);
  if (!whole)
    throw core::ArgumentError(what, std::string("'") + name + "' must be a whole number >= 0");
  return value.is_number_unsigned() ? value.get<std::uint64_t>()
                                    : static_cast<std::uint64_t>(value.get<double>());
}

bool bool_field(const json& request, const char* what, const char* name, bool otherwise) {
  const auto it = request.find(name);
  if (it == request.end()) return otherwise;
  if (!it->is_boolean())
    throw core::ArgumentError(what, std::string("'") + name + "' must be true or false");
  return it->get<bool>();
}

EditKind kind_of(const std::string& kind) {
  for (const auto& [name, value] : {std::pair{"gamma", EditKind::gamma},
                                    {"threshold", EditKind::threshold},
                                    {"beta", EditKind::beta},
                                    {"class", EditKind::class_weight},
                                    {"isotropic", EditKind::isotropic},
                                    {"scale-thresholds", EditKind::scale_thresholds}})
    if (kind == name) return value;
  throw core::ArgumentError("edit", "unknown kind '" + kind +
                                        "' (gamma, threshold, beta, class, isotropic, "
                                        "scale-thresholds)");
}

// Names from the user's files may hold invalid UTF-8: replaced, never thrown on.
std::string text(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

json model_json(const model::ShapeProcessModel& m) {
  json categories = json::array(), pairs = json::array(), classes = json::array();
  for (const auto& c : m.categories)
    categories.push_back(
        {{"name", c.name}, {"beta", c.beta}, {"status", to_string(c.beta_status)}});
  for (const auto& pair : m.interactions) {
    json axes = json::array();
    for (const auto& a : pair.axes) {
      json status = json::array();
      for (const auto s : a.status) status.push_back(to_string(s));
      axes.push_back({{"direction", {a.direction.x(), a.direction.y()}},
                      {"thresholds", a.thresholds},
                      {"gammas", a.gammas},
                      {"status", status}});
    }
    pairs.push_back({{"first", pair.first}, {"second", pair.second}, {"axes", axes}});
  }
  for (const auto& c : m.shape_classes)
    classes.push_back({{"category", c.category}, {"weight", c.weight}, {"label", c.label}});
  return {{"units", m.units},
          {"categories", categories},
          {"pairs", pairs},
          {"classes", classes},
          {"range", m.interaction_range()}};
}

}  // namespace

ModelEdit parse_edit(const std::string& body) {
  const json request = parse_object(body, "edit");
  const json& kind = field(request, "edit", "kind");
  if (!kind.is_string()) throw core::ArgumentError("edit", "'kind' must be a string");
  ModelEdit edit;
  edit.kind = kind_of(kind.get<std::string>());
  switch (edit.kind) {
    case EditKind::gamma:
    case EditKind::threshold:
      edit.pair = whole_field(request, "edit", "pair");
      edit.every_axis = bool_field(request, "edit", "every_axis", false);
      if (!edit.every_axis) edit.axis = whole_field(request, "edit", "axis");
      edit.index = whole_field(request, "edit", "index");
      edit.value = number_field(request, "edit", "value");
      break;
    case EditKind::beta:
    case EditKind::class_weight:
      edit.index = whole_field(request, "edit", "index");
      edit.value = number_field(request, "edit", "value");
      break;
    case EditKind::scale_thresholds:
      edit.value = number_field(request, "edit", "value");
      break;
    case EditKind::isotropic:
      break;
  }
  if (edit.value < 0) throw core::ArgumentError("edit", "'value' must not be negative");
  return edit;
}

ExportRequest parse_export(const std::string& body) {
  const json request = parse_object(body, "export");
  const json& name = field(request, "export", "name");
  if (!name.is_string()) throw core::ArgumentError("export", "'name' must be a string");
  return {name.get<std::string>(), bool_field(request, "export", "overwrite", false)};
}

SeedRequest parse_seed(const std::string& body) {
  const json request = parse_object(body, "seed");
  if (bool_field(request, "seed", "reroll", false)) return {true, 0};
  return {false, whole_field(request, "seed", "seed")};
}

bool parse_full(const std::string& body) {
  const json request = parse_object(body, "size");
  if (!request.contains("full")) throw core::ArgumentError("size", "'full' is missing");
  return bool_field(request, "size", "full", false);
}

std::string state_json(const StudioState& s) {
  json out = {{"phase", s.phase == Phase::fitting ? "fitting"
                        : s.phase == Phase::ready ? "ready"
                                                  : "failed"},
              {"fit",
               {{"stage", s.fit.stage},
                {"done", s.fit.done},
                {"total", s.fit.total},
                {"seconds", s.fit.seconds}}},
              {"error", s.error},
              {"edits", s.edits},
              {"can_undo", s.can_undo},
              {"can_redo", s.can_redo},
              {"seed", s.seed},
              {"full", s.full},
              {"size", s.size},
              {"revision", s.revision},
              {"has_exemplar", s.has_exemplar}};
  if (s.model) out["model"] = model_json(*s.model);
  return text(out);
}

std::string preview_json(const Preview& p) {
  json verdicts = json::array();
  for (const auto& v : p.verdicts)
    verdicts.push_back({{"metric", v.metric},
                        {"shown", v.shown},
                        {"rule", v.rule},
                        {"outcome", evaluation::to_string(v.outcome)},
                        {"problem", v.problem}});
  return text(json{{"sequence", p.sequence},
                   {"revision", p.revision},
                   {"stage", p.stage == PreviewStage::draft   ? "draft"
                             : p.stage == PreviewStage::final ? "final"
                                                              : "cut"},
                   {"svg", p.svg},
                   {"elements", p.elements},
                   {"steps", p.steps},
                   {"stationary", p.stationary},
                   {"seconds", p.seconds},
                   {"seed", p.seed},
                   {"size", p.size},
                   {"verdicts", verdicts},
                   {"summary", p.summary},
                   {"note", p.note}});
}

std::string export_json(const ExportResult& result) {
  json files = json::array();
  for (const auto& f : result.files) files.push_back(f.string());
  return text(json{{"files", files}, {"command", result.command}});
}

std::string error_json(const std::string& message) { return text(json{{"error", message}}); }

}  // namespace shapeproc::studio::detail
