#include "api/read_region.hpp"

#include <utility>
#include <vector>

#include "api/curve_or_path.hpp"
#include "api/write_json.hpp"

namespace bezier::api {

namespace {

std::string point_text(core::Point2 p) {
  std::string out = "(";
  append_json_number(p.x, out);
  out += ", ";
  append_json_number(p.y, out);
  return out + ")";
}

std::optional<std::vector<core::Curve>> read_curves(RequestReader& reader, const Json& value,
                                                    const std::string& pointer) {
  if (!value.is_array()) {
    reader.fail(pointer, "expected an array of curves, each an array of control points [x, y]");
    return std::nullopt;
  }
  const auto limit = static_cast<std::size_t>(reader.limits().max_path_segments);
  if (value.size() > limit) {
    reader.fail_limit(
        pointer, "more than " + std::to_string(limit) + " curves (the max_path_segments limit)");
    return std::nullopt;
  }
  std::vector<core::Curve> curves;
  curves.reserve(value.size());
  bool all_read = true;
  for (std::size_t k = 0; k < value.size(); ++k) {
    auto curve = reader.curve2(value[k], pointer_to(pointer, k));
    if (curve) {
      curves.push_back(std::move(*curve));
    } else {
      all_read = false;
    }
  }
  if (!all_read) return std::nullopt;
  if (const auto k = region::chain_break(curves)) {
    reader.fail(pointer_to(pointer_to(pointer, *k), std::size_t{0}),
                "curve " + std::to_string(*k) + " starts at " + point_text(curves[*k].front()) +
                    ", not at the end of curve " + std::to_string(*k - 1) + " " +
                    point_text(curves[*k - 1].back()) +
                    ", which does not close its chain (a chain closes when a curve ends where "
                    "the chain started; the next curve may then start anywhere)");
    return std::nullopt;
  }
  return curves;
}

/// The member `key` of `object`, null included: a null is refused, not taken for a missing
/// member (as read_path does with a null path).
const Json* member(const Json& object, std::string_view key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

}  // namespace

std::optional<region::Region> read_region(RequestReader& reader, const Json& object,
                                          const std::string& pointer,
                                          std::optional<double> arc_tolerance) {
  if (!object.is_object()) {
    reader.fail(pointer, "expected an object with \"path\" or \"curves\", and \"fill_rule\"");
    return std::nullopt;
  }
  region::FillRule rule = region::FillRule::nonzero;
  bool rule_ok = true;
  if (const Json* value = member(object, "fill_rule")) {
    const auto name =
        reader.one_of(*value, pointer_to(pointer, "fill_rule"),
                      {to_string(region::FillRule::nonzero), to_string(region::FillRule::evenodd)});
    rule_ok = name.has_value();
    if (name && *name == to_string(region::FillRule::evenodd)) rule = region::FillRule::evenodd;
  }
  const Json* curves = member(object, "curves");
  const bool has_path_member = has_path(object);
  if (curves != nullptr && has_path_member) {
    reader.fail(pointer, "give either \"path\" or \"curves\", not both");
    return std::nullopt;
  }
  if (curves == nullptr && !has_path_member) {
    reader.fail(pointer_to(pointer, "path"),
                "required field is missing (or give \"curves\": Bézier curves of any degree)");
    return std::nullopt;
  }
  if (has_path_member) {
    auto parse = read_parsed_path(reader, object.at("path"), pointer_to(pointer, "path"), arc_tolerance,
                                  EmptyPath::accepted);
    auto path = parse ? std::optional<path::Path>(std::move(parse->path)) : std::nullopt;
    if (!path || !rule_ok) return std::nullopt;
    return region::region_from_path(std::move(*path), rule);
  }
  auto read = read_curves(reader, *curves, pointer_to(pointer, "curves"));
  if (!read || !rule_ok) return std::nullopt;
  return region::region_from_curves(std::move(*read), rule);
}

}  // namespace bezier::api
