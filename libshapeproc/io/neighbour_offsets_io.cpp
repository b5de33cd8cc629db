#include "libshapeproc/io/neighbour_offsets_io.hpp"

#include <limits>
#include <nlohmann/json.hpp>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::io {

using nlohmann::json;

json neighbour_offsets_json(const model::NeighbourOffsets& offsets, int dimension) {
  json rows = json::array();
  for (const model::NeighbourOffset& o : offsets.offsets) {
    json row = {o.from, o.to, o.offset.x(), o.offset.y()};
    if (dimension == 3) row.push_back(o.offset.z());
    row.push_back(o.weight);
    rows.push_back(std::move(row));
  }
  return {{"share", offsets.share}, {"radii", offsets.radii}, {"offsets", rows}};
}

namespace {

[[noreturn]] void fail(const std::string& file_name, const std::string& where,
                       const std::string& what) {
  throw core::InputError(file_name, 0, "neighbour_offsets" + where + ": " + what);
}

int kind(const json& v, const std::string& file_name, const std::string& where) {
  if (!v.is_number_integer() || v.get<long long>() < 0 ||
      v.get<long long>() > std::numeric_limits<int>::max())
    fail(file_name, where, "expected a shape or category index, got " + v.dump());
  return v.get<int>();
}

double number(const json& v, const std::string& file_name, const std::string& where) {
  if (!v.is_number()) fail(file_name, where, "expected a number, got " + v.dump());
  return v.get<double>();
}

}  // namespace

model::NeighbourOffsets parse_neighbour_offsets(const json& object, int dimension,
                                                const std::string& file_name) {
  if (!object.is_object() || !object.contains("radii") || !object.contains("offsets") ||
      !object["radii"].is_array() || !object["offsets"].is_array())
    fail(file_name, "", "expected an object with the arrays \"radii\" and \"offsets\"");
  model::NeighbourOffsets out;
  if (object.contains("share")) out.share = number(object["share"], file_name, ".share");
  const json& radii = object["radii"];
  for (std::size_t r = 0; r < radii.size(); ++r)
    out.radii.push_back(number(radii[r], file_name, ".radii[" + std::to_string(r) + "]"));
  const json& rows = object["offsets"];
  const std::size_t width = dimension == 3 ? 6 : 5;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::string where = ".offsets[" + std::to_string(k) + "]";
    if (!rows[k].is_array() || rows[k].size() != width)
      fail(file_name, where,
           "expected [from, to, " + std::string(dimension == 3 ? "x, y, z" : "x, y") + ", weight]");
    model::NeighbourOffset o;
    o.from = kind(rows[k][0], file_name, where + "[0]");
    o.to = kind(rows[k][1], file_name, where + "[1]");
    for (int axis = 0; axis < dimension; ++axis)
      o.offset[axis] = number(rows[k][static_cast<std::size_t>(2 + axis)], file_name,
                              where + "[" + std::to_string(2 + axis) + "]");
    o.weight = number(rows[k][width - 1], file_name, where + "[" + std::to_string(width - 1) + "]");
    out.offsets.push_back(o);
  }
  return out;
}

}  // namespace shapeproc::io
