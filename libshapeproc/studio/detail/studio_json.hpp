// The studio's requests and answers as JSON: the page's edits parsed and checked into typed
// records, the session's state and previews written for the page. Only the server uses it.
#pragma once

#include <string>

#include "libshapeproc/studio/studio_session.hpp"

namespace shapeproc::studio::detail {

// An edit request: {"kind": "gamma", "pair": 0, "axis": 0, "index": 0, "value": 2.5,
// "every_axis": false}. Throws core::ArgumentError naming the field that is missing, of the
// wrong type, negative or not finite, and for anything that is not such an object.
ModelEdit parse_edit(const std::string& body);

struct ExportRequest {
  std::string name;
  bool overwrite = false;
};
ExportRequest parse_export(const std::string& body);

// {"seed": N} (a whole number) or {"reroll": true}; {"full": bool}.
struct SeedRequest {
  bool reroll = false;
  std::uint64_t seed = 0;
};
SeedRequest parse_seed(const std::string& body);
bool parse_full(const std::string& body);

std::string state_json(const StudioState& state);
std::string preview_json(const Preview& preview);
std::string export_json(const ExportResult& result);
std::string error_json(const std::string& message);

}  // namespace shapeproc::studio::detail
