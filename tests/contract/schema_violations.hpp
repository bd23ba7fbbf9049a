#pragma once
// Negative contract: requests generated from the spec's request schemas, each breaking
// one constraint of a valid example (a type, a bound, an array length, a required or
// unknown member, a oneOf/not rule), so that every constraint the spec states is sent
// to the service at least once and must be answered with the documented 4xx problem.
//
// A "site" names one constraint where it applies: the instance path with array indices
// as `*`, and the JSON Pointer of the schema keyword, e.g.
//   "/points/*/* @ /components/schemas/Number/type".
// sites() lists every site of a request schema (all branches, all members); violations()
// generates from one example what it can reach. The contract test requires the union
// over an operation's examples to cover every site.

#include "tests/support/openapi_validator.hpp"  // first: see there

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace bezier::test {

struct SchemaViolation {
  nlohmann::json request;             ///< the example with one constraint broken
  std::string site;                   ///< which constraint (see above)
  std::string what;                   ///< what was done to the example
  std::vector<std::string> pointers;  ///< where the service's errors may point
};

class ViolationGenerator {
 public:
  explicit ViolationGenerator(const OpenApiContract& contract) : contract_(contract) {}

  /// Every constraint site of the schema at `location`.
  [[nodiscard]] std::set<std::string> sites(const std::string& location) const {
    std::set<std::string> out;
    collect_sites(location, "", out, 0);
    return out;
  }

  /// Requests breaking one constraint each, made from `example` (valid for the schema at
  /// `location`). Only requests the schema really rejects are returned.
  [[nodiscard]] std::vector<SchemaViolation> violations(const std::string& location,
                                                        const nlohmann::json& example) const {
    return candidates(location, example, /*accepted=*/false);
  }

  /// Requests breaking one constraint each, made from `example`, that the schema at
  /// `location` accepts all the same: the constraint told one whole shape of the request
  /// (a oneOf branch) from another, and the request has the other shape (a /polar at
  /// parameters without its `t` is a /polar of neither `t` nor `samples`). The service
  /// must take them too; they are how such a constraint is exercised.
  [[nodiscard]] std::vector<SchemaViolation> crossings(const std::string& location,
                                                       const nlohmann::json& example) const {
    return candidates(location, example, /*accepted=*/true);
  }

  /// Requests exactly at one bound each (a minimum or maximum value, an array of
  /// exactly minItems or maxItems), made from `example`: the schema accepts them, so
  /// the service must too. This catches a spec looser than the service.
  [[nodiscard]] std::vector<SchemaViolation> boundaries(const std::string& location,
                                                        const nlohmann::json& example) const {
    std::vector<SchemaViolation> candidates;
    std::vector<SchemaViolation> edges;
    Walk walk{example, candidates, edges};
    generate(walk, location, "", "", {}, 0);
    std::vector<SchemaViolation> out;
    for (auto& e : edges) {
      if (contract_.schema_errors(location, e.request).empty()) out.push_back(std::move(e));
    }
    return out;
  }

  /// Every bound of the schema at `location` (the sites boundaries() can reach).
  [[nodiscard]] std::set<std::string> bound_sites(const std::string& location) const {
    std::set<std::string> out;
    for (const auto& s : sites(location)) {
      for (const char* k : {"/minimum", "/maximum", "/minItems", "/maxItems"}) {
        const std::string suffix(k);
        if (s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0) out.insert(s);
      }
    }
    return out;
  }

  /// A value the schema at `location` accepts: its first example, const or enum value,
  /// or the smallest value of its type within its bounds.
  [[nodiscard]] nlohmann::json synthesize(const std::string& location) const {
    const std::string loc = contract_.resolve(location);
    const nlohmann::json& node = contract_.at(loc);
    if (node.contains("examples")) return node.at("examples").at(0);
    if (node.contains("const")) return node.at("const");
    if (node.contains("enum")) return node.at("enum").at(0);
    for (const char* k : {"oneOf", "anyOf"}) {
      if (node.contains(k)) return synthesize(loc + "/" + k + "/0");
    }
    const std::string type = first_type(node);
    if (type == "number") {
      double v = 0.5;
      if (node.contains("minimum")) v = std::max(v, node.at("minimum").get<double>());
      if (node.contains("maximum")) v = std::min(v, node.at("maximum").get<double>());
      return v;
    }
    if (type == "integer") return node.contains("minimum") ? node.at("minimum").get<long long>() : 1LL;
    if (type == "string") return "x";
    if (type == "boolean") return true;
    if (type == "array") {
      nlohmann::json a = nlohmann::json::array();
      const long long n = node.value("minItems", 0LL);
      const std::size_t positions = member_or_empty(node, "prefixItems").size();
      for (long long i = 0; i < n; ++i) {
        const auto at = static_cast<std::size_t>(i);
        a.push_back(synthesize(at < positions ? loc + "/prefixItems/" + std::to_string(at) : loc + "/items"));
      }
      return a;
    }
    if (type == "object") {
      nlohmann::json o = nlohmann::json::object();
      for (const auto& name : member_or_empty(node, "required")) {
        o[name.get<std::string>()] = synthesize(loc + "/properties/" + pointer_token(name.get<std::string>()));
      }
      return o;
    }
    return nullptr;
  }

 private:
  struct Walk {
    const nlohmann::json& root;
    std::vector<SchemaViolation>& out;    ///< constraint broken
    std::vector<SchemaViolation>& edges;  ///< exactly at a bound
  };

  /// The requests made from `example` that break one constraint each, those the schema
  /// at `location` rejects (accepted false) or accepts all the same (accepted true).
  [[nodiscard]] std::vector<SchemaViolation> candidates(const std::string& location,
                                                        const nlohmann::json& example, bool accepted) const {
    std::vector<SchemaViolation> made;
    std::vector<SchemaViolation> edges;
    Walk walk{example, made, edges};
    generate(walk, location, "", "", {}, 0);
    std::vector<SchemaViolation> out;
    for (auto& c : made) {
      if (contract_.schema_errors(location, c.request).empty() == accepted) out.push_back(std::move(c));
    }
    return out;
  }

  static constexpr int kMaxDepth = 40;
  static constexpr const char* kUnknownMember = "unexpected_member";

  static std::string site(const std::string& pattern, const std::string& keyword_location) {
    return pattern + " @ " + keyword_location;
  }

  static std::string first_type(const nlohmann::json& node) {
    if (!node.contains("type")) return "";
    const auto& t = node.at("type");
    if (t.is_string()) return t.get<std::string>();
    for (const auto& e : t) {
      if (e != "null") return e.get<std::string>();
    }
    return "null";
  }

  static bool type_allows(const nlohmann::json& node, const nlohmann::json& value) {
    if (!node.contains("type")) return true;
    const auto allows = [&](const std::string& t) {
      if (t == "null") return value.is_null();
      if (t == "boolean") return value.is_boolean();
      if (t == "string") return value.is_string();
      if (t == "array") return value.is_array();
      if (t == "object") return value.is_object();
      if (t == "number") return value.is_number();
      if (t == "integer") return value.is_number_integer() || value.is_number_unsigned();
      return false;
    };
    const auto& t = node.at("type");
    if (t.is_string()) return allows(t.get<std::string>());
    for (const auto& e : t) {
      if (allows(e.get<std::string>())) return true;
    }
    return false;
  }

  /// A schema that only admits null (a oneOf branch, or a member of a request's other
  /// shape, `Absent`) stands for "the same as absent": nothing to break.
  static bool is_null_only(const nlohmann::json& node) {
    if (!node.is_object() || !node.contains("type") || node.at("type") != "null") return false;
    return std::all_of(node.items().begin(), node.items().end(),
                       [](const auto& member) { return member.key() == "type" || member.key() == "description"; });
  }

  void collect_sites(const std::string& location, const std::string& pattern,
                     std::set<std::string>& out, int depth) const {
    if (depth > kMaxDepth) return;
    const std::string loc = contract_.resolve(location);
    const nlohmann::json& node = contract_.at(loc);
    if (!node.is_object() || is_null_only(node)) return;
    for (const char* k : {"type", "enum", "const", "minimum", "maximum", "exclusiveMinimum",
                          "exclusiveMaximum", "minItems", "maxItems", "oneOf", "not"}) {
      if (node.contains(k)) out.insert(site(pattern, loc + "/" + k));
    }
    if (node.value("additionalProperties", true) == false) out.insert(site(pattern, loc + "/additionalProperties"));
    for (const auto& name : member_or_empty(node, "required")) {
      out.insert(site(pattern, loc + "/required/" + pointer_token(name.get<std::string>())));
    }
    if (node.contains("properties")) {
      for (const auto& [name, sub] : node.at("properties").items()) {
        collect_sites(loc + "/properties/" + pointer_token(name), pattern + "/" + pointer_token(name), out, depth + 1);
      }
    }
    if (node.contains("items")) collect_sites(loc + "/items", pattern + "/*", out, depth + 1);
    for (std::size_t i = 0; i < member_or_empty(node, "prefixItems").size(); ++i) {
      collect_sites(loc + "/prefixItems/" + std::to_string(i), pattern + "/*", out, depth + 1);
    }
    for (const char* k : {"oneOf", "anyOf", "allOf"}) {
      if (!node.contains(k)) continue;
      for (std::size_t i = 0; i < node.at(k).size(); ++i) {
        collect_sites(loc + "/" + k + "/" + std::to_string(i), pattern, out, depth + 1);
      }
    }
  }

  void add(Walk& walk, nlohmann::json request, std::string at_site, std::string what,
           std::vector<std::string> pointers, const std::vector<std::string>& also) const {
    pointers.insert(pointers.end(), also.begin(), also.end());
    walk.out.push_back({std::move(request), std::move(at_site), std::move(what), std::move(pointers)});
  }

  /// The example with the value at `pointer` replaced.
  static nlohmann::json replaced(const nlohmann::json& root, const std::string& pointer, nlohmann::json value) {
    if (pointer.empty()) return value;
    nlohmann::json copy = root;
    copy[nlohmann::json::json_pointer(pointer)] = std::move(value);
    return copy;
  }

  void generate(Walk& walk, const std::string& location, const std::string& pointer,
                const std::string& pattern, const std::vector<std::string>& also, int depth) const {
    if (depth > kMaxDepth) return;
    const std::string loc = contract_.resolve(location);
    const nlohmann::json& node = contract_.at(loc);
    if (!node.is_object()) return;
    const nlohmann::json& value = walk.root.at(nlohmann::json::json_pointer(pointer));
    const auto here = [&](const std::string& keyword) { return site(pattern, loc + "/" + keyword); };

    if (node.contains("type")) {
      // A value of a type the schema does not allow, and null where null is not allowed.
      for (const nlohmann::json& candidate : {nlohmann::json("not-a-number"), nlohmann::json(true),
                                               nlohmann::json(0.5), nlohmann::json(nullptr)}) {
        if (type_allows(node, candidate)) continue;
        add(walk, replaced(walk.root, pointer, candidate), here("type"), "set to " + candidate.dump(), {pointer}, also);
      }
    }
    if (node.contains("const") && node.at("const").is_string()) {
      add(walk, replaced(walk.root, pointer, node.at("const").get<std::string>() + "-x"), here("const"),
          "not the constant", {pointer}, also);
    }
    if (node.contains("enum")) {
      add(walk, replaced(walk.root, pointer, "no-such-value"), here("enum"), "not in the enum", {pointer}, also);
    }
    if (value.is_number()) {
      const auto bound = [&](const char* keyword, double delta) {
        if (!node.contains(keyword)) return;
        const nlohmann::json& b = node.at(keyword);
        const nlohmann::json v = b.is_number_integer() ? nlohmann::json(b.get<long long>() + static_cast<long long>(delta))
                                                       : nlohmann::json(b.get<double>() + delta);
        add(walk, replaced(walk.root, pointer, v), here(keyword), std::string(keyword) + " broken: " + v.dump(), {pointer}, also);
        if (delta != 0.0) {
          walk.edges.push_back({replaced(walk.root, pointer, b), here(keyword), std::string("at the ") + keyword, {pointer}});
        }
      };
      bound("minimum", -1.0);
      bound("maximum", 1.0);
      bound("exclusiveMinimum", 0.0);
      bound("exclusiveMaximum", 0.0);
    }
    if (value.is_array()) {
      if (node.contains("minItems") && value.size() >= node.at("minItems").get<std::size_t>()) {
        nlohmann::json edge = value;
        edge.erase(edge.begin() + node.at("minItems").get<long long>(), edge.end());
        walk.edges.push_back({replaced(walk.root, pointer, edge), here("minItems"), "cut to minItems", {pointer}});
      }
      if (node.contains("maxItems") && !value.empty()) {
        nlohmann::json edge = value;
        while (edge.size() < node.at("maxItems").get<std::size_t>()) edge.push_back(value.back());
        walk.edges.push_back({replaced(walk.root, pointer, edge), here("maxItems"), "grown to maxItems", {pointer}});
      }
      if (node.contains("minItems") && node.at("minItems").get<long long>() >= 1) {
        nlohmann::json shorter = value;
        shorter.erase(shorter.begin() + (node.at("minItems").get<long long>() - 1), shorter.end());
        add(walk, replaced(walk.root, pointer, shorter), here("minItems"),
            "cut to " + std::to_string(shorter.size()) + " items", {pointer}, also);
      }
      if (node.contains("maxItems") && !value.empty()) {
        nlohmann::json longer = value;
        while (longer.size() <= node.at("maxItems").get<std::size_t>()) longer.push_back(value.back());
        add(walk, replaced(walk.root, pointer, longer), here("maxItems"),
            "grown to " + std::to_string(longer.size()) + " items", {pointer}, also);
      }
      // The first and the last element: a bound such as "t1 <= 1" may only be reachable
      // at the end of an increasing pair.
      if (node.contains("items") && node.at("items").is_object() && !value.empty()) {
        generate(walk, loc + "/items", pointer + "/0", pattern + "/*", also, depth + 1);
        if (value.size() > 1) {
          generate(walk, loc + "/items", pointer + "/" + std::to_string(value.size() - 1), pattern + "/*", also, depth + 1);
        }
      }
      // A tuple (prefixItems): every position, each with its own schema.
      const std::size_t positions = std::min(member_or_empty(node, "prefixItems").size(), value.size());
      for (std::size_t i = 0; i < positions; ++i) {
        generate(walk, loc + "/prefixItems/" + std::to_string(i), pointer + "/" + std::to_string(i), pattern + "/*",
                 also, depth + 1);
      }
    }
    if (value.is_object()) {
      for (const auto& name : member_or_empty(node, "required")) {
        const std::string key = name.get<std::string>();
        if (!value.contains(key)) continue;
        nlohmann::json without = value;
        without.erase(key);
        add(walk, replaced(walk.root, pointer, without), here("required/" + pointer_token(key)),
            "removed " + key, {pointer + "/" + pointer_token(key)}, also);
      }
      if (node.value("additionalProperties", true) == false) {
        nlohmann::json more = value;
        more[kUnknownMember] = 1;
        add(walk, replaced(walk.root, pointer, more), here("additionalProperties"),
            std::string("added ") + kUnknownMember, {pointer + "/" + kUnknownMember}, also);
      }
      if (node.contains("properties")) {
        for (const auto& [name, sub] : node.at("properties").items()) {
          if (!value.contains(name)) continue;
          generate(walk, loc + "/properties/" + pointer_token(name), pointer + "/" + pointer_token(name),
                   pattern + "/" + pointer_token(name), also, depth + 1);
        }
      }
    }
    generate_combinators(walk, loc, node, value, pointer, pattern, also, depth);
  }

  void generate_combinators(Walk& walk, const std::string& loc, const nlohmann::json& node,
                            const nlohmann::json& value, const std::string& pointer,
                            const std::string& pattern, const std::vector<std::string>& also,
                            int depth) const {
    const auto here = [&](const std::string& keyword) { return site(pattern, loc + "/" + keyword); };
    if (node.contains("oneOf")) {
      // Members that decide the branch ("exactly one of t and samples"): the service may
      // point at any of them when a branch's rule is broken.
      // A branch may be a whole schema ($ref): its required members, synthesized from its
      // own properties ("points or path": both given).
      std::vector<std::string> deciding = also;
      nlohmann::json all = value;
      for (std::size_t i = 0; i < node.at("oneOf").size(); ++i) {
        const std::string branch = contract_.resolve(loc + "/oneOf/" + std::to_string(i));
        const nlohmann::json& own = member_or_empty(contract_.at(branch), "properties");
        for (const auto& name : member_or_empty(contract_.at(branch), "required")) {
          const std::string key = name.get<std::string>();
          deciding.push_back(pointer + "/" + pointer_token(key));
          if (value.is_object() && !value.contains(key)) {
            const std::string owner = own.is_object() && own.contains(key) ? branch : loc;
            all[key] = synthesize(owner + "/properties/" + pointer_token(key));
          }
        }
      }
      if (value.is_object() && all != value) {
        add(walk, replaced(walk.root, pointer, all), here("oneOf"), "gave the members of every branch", {}, deciding);
      }
      add(walk, replaced(walk.root, pointer, "not-a-number"), here("oneOf"), "matches no branch", {pointer}, also);
      for (std::size_t i = 0; i < node.at("oneOf").size(); ++i) {
        const std::string branch = loc + "/oneOf/" + std::to_string(i);
        if (contract_.schema_errors(branch, value).empty()) generate(walk, branch, pointer, pattern, deciding, depth + 1);
      }
    }
    for (const char* k : {"anyOf", "allOf"}) {
      if (!node.contains(k)) continue;
      for (std::size_t i = 0; i < node.at(k).size(); ++i) {
        const std::string branch = loc + "/" + k + "/" + std::to_string(i);
        if (contract_.schema_errors(branch, value).empty()) generate(walk, branch, pointer, pattern, also, depth + 1);
      }
    }
    if (node.contains("not")) {
      // Make the value match what is forbidden: the forbidden type, or the forbidden
      // combination of members.
      const nlohmann::json& forbidden = contract_.at(contract_.resolve(loc + "/not"));
      if (forbidden.contains("type") && forbidden.at("type") == "null") {
        add(walk, replaced(walk.root, pointer, nullptr), here("not"), "set to null", {pointer}, also);
      } else if (forbidden.contains("required") && value.is_object()) {
        nlohmann::json all = value;
        std::vector<std::string> named;
        for (const auto& name : forbidden.at("required")) {
          const std::string key = name.get<std::string>();
          named.push_back(pointer + "/" + pointer_token(key));
          if (!value.contains(key)) all[key] = synthesize(loc + "/properties/" + pointer_token(key));
        }
        add(walk, replaced(walk.root, pointer, all), here("not"), "gave all of " + forbidden.at("required").dump(),
            named, also);
      }
    }
  }

  const OpenApiContract& contract_;
};

}  // namespace bezier::test
