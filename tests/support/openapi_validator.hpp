#pragma once
// Checks HTTP exchanges against api/openapi.yaml, so a test fails when the service and
// its contract drift apart: a status, media type or body the spec does not describe,
// or a request the service accepted although the spec forbids it.
//
// The YAML is turned into JSON by tools/openapi_to_json.py (Debian's
// python3-yaml, read as YAML 1.2), and schemas are checked with valijson (Debian's
// libvalijson-dev, JSON Schema draft 7 with nlohmann-json). The spec therefore keeps to
// the part of OpenAPI 3.1 / JSON Schema 2020-12 that draft 7 reads the same way (no
// constraints beside a $ref, `type: [x, 'null']` for nullable), and tuples in
// 2020-12's `prefixItems`, which as_draft7() turns into draft 7's array form of `items`.
//
// Usage (any test that talks to the service); this header must be the FIRST include of
// the test file (see below), and it brings <httplib.h> itself:
//   #include "tests/support/openapi_validator.hpp"
//   ...
//   const auto r = client.Post("/evaluate", body, "application/json");
//   bezier::test::expect_conforms("POST", "/evaluate", "application/json", body, r);

// GCC 12 at -O3 reports false warnings in code this header instantiates: -Wrestrict in
// valijson's JSON Pointer code (std::string::replace inlined), and, with
// -fsanitize=address,undefined, -Wmaybe-uninitialized in libstdc++'s <regex> (a
// std::function moved in regex_automaton.h; valijson supports `pattern`). GCC decides by
// the pragma state where the warned-about line was read, so <functional> and <regex>
// must be read first here, under these pragmas: hence "first include".
#if defined(_GLIBCXX_STD_FUNCTION_H) || defined(_GLIBCXX_REGEX) || defined(CPPHTTPLIB_HTTPLIB_H)
#error "include tests/support/openapi_validator.hpp before any other header (GCC 12 false warnings in <regex>)"
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wrestrict"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <functional>
#include <regex>

#include <httplib.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

namespace bezier::test {

/// One request and its answer, as seen on the wire.
struct HttpExchange {
  std::string method;                ///< GET, HEAD, POST, PUT, ...
  std::string path;                  ///< e.g. /evaluate (a query string is ignored)
  std::string request_content_type;  ///< empty when the request had no body
  std::string request_body;
  int status = 0;
  std::string response_content_type;
  std::string response_body;
  /// Response headers by lower-case name; checked only when `headers_known`.
  std::map<std::string, std::string> response_headers;
  bool headers_known = false;
};

/// The media type without parameters, lower case: "text/plain; charset=utf-8" -> "text/plain".
[[nodiscard]] inline std::string media_type_of(const std::string& content_type) {
  std::string out;
  for (const char c : content_type.substr(0, content_type.find(';'))) {
    if (c != ' ' && c != '\t') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

[[nodiscard]] inline bool is_json_media_type(const std::string& media_type) {
  return media_type == "application/json" ||
         (media_type.size() > 5 && media_type.compare(media_type.size() - 5, 5, "+json") == 0);
}

/// JSON Schema 2020-12 (and the service) count 3.0 as an integer; valijson's strict mode
/// does not. Integral doubles are made integers before validation (a `number` schema
/// accepts both, so nothing else changes).
[[nodiscard]] inline nlohmann::json with_integral_numbers_as_integers(const nlohmann::json& value) {
  if (value.is_number_float()) {
    const double v = value.get<double>();
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.0e15) {
      return nlohmann::json(static_cast<std::int64_t>(v));
    }
    return value;
  }
  if (value.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& e : value) out.push_back(with_integral_numbers_as_integers(e));
    return out;
  }
  if (value.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [k, e] : value.items()) out[k] = with_integral_numbers_as_integers(e);
    return out;
  }
  return value;
}

/// The schema as draft 7 reads it: 2020-12's `prefixItems` (a tuple's positions) is
/// draft 7's array form of `items`, and a 2020-12 `items` beside it (the items after
/// them) is draft 7's `additionalItems`. Every object with a `prefixItems` array is
/// rewritten; the spec has no member of that name outside schemas.
[[nodiscard]] inline nlohmann::json as_draft7(nlohmann::json node) {
  if (node.is_array()) {
    for (auto& e : node) e = as_draft7(std::move(e));
    return node;
  }
  if (!node.is_object()) return node;
  for (auto& [key, member] : node.items()) member = as_draft7(std::move(member));
  if (node.contains("prefixItems") && node.at("prefixItems").is_array()) {
    if (node.contains("items")) node["additionalItems"] = std::move(node.at("items"));
    node["items"] = std::move(node.at("prefixItems"));
    node.erase("prefixItems");
  }
  return node;
}

/// The member `key` of `node` by reference, or null (which iterates as nothing) when it
/// is absent: safe in a range-for, unlike a temporary from json::value().
[[nodiscard]] inline const nlohmann::json& member_or_empty(const nlohmann::json& node, const std::string& key) {
  static const nlohmann::json kAbsent;
  if (!node.is_object()) return kAbsent;
  const auto it = node.find(key);
  return it == node.end() ? kAbsent : *it;
}

/// JSON Pointer token escaping (RFC 6901).
[[nodiscard]] inline std::string pointer_token(const std::string& key) {
  std::string out;
  for (const char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

/// Reads api/openapi.yaml (or any OpenAPI YAML) as JSON through the converter script.
[[nodiscard]] inline nlohmann::json load_openapi_json(const std::string& yaml_path,
                                                      const std::string& source_dir = BEZIER_SOURCE_DIR) {
  std::string python = "python3";
  if (const char* given = std::getenv("BEZIER_PYTHON3")) {
    python = given;
  } else if (access("/usr/bin/python3", X_OK) == 0) {
    python = "/usr/bin/python3";  // Debian's, where python3-yaml installs
  }
  const std::string command =
      "'" + python + "' '" + source_dir + "/tools/openapi_to_json.py' '" + yaml_path + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  std::string text;
  char buf[65536];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, n);
  const int rc = pclose(pipe);
  if (rc != 0) {
    throw std::runtime_error(command + " failed (exit status " + std::to_string(rc) +
                             "); is python3-yaml installed?");
  }
  return nlohmann::json::parse(text);
}

/// The OpenAPI document with every JSON schema in it compiled on first use.
class OpenApiContract {
 public:
  explicit OpenApiContract(nlohmann::json spec) : spec_(std::move(spec)) {}

  [[nodiscard]] const nlohmann::json& spec() const noexcept { return spec_; }

  /// The node at a local reference "#/a/b" or JSON Pointer "/a/b".
  [[nodiscard]] const nlohmann::json& at(const std::string& reference) const {
    const std::string pointer = reference.rfind("#", 0) == 0 ? reference.substr(1) : reference;
    return spec_.at(nlohmann::json::json_pointer(pointer));
  }

  /// Follows `$ref` (OpenAPI reference objects and schemas alike) from the node at
  /// `location` and returns the location of the node finally referred to.
  [[nodiscard]] std::string resolve(std::string location) const {
    for (int hops = 0; hops < 32; ++hops) {
      const nlohmann::json& node = at(location);
      if (!node.is_object() || !node.contains("$ref")) return location;
      location = node.at("$ref").get<std::string>().substr(1);
    }
    throw std::runtime_error("$ref chain too long at " + location);
  }

  /// Every way `instance` breaks the schema at `schema_location` (a JSON Pointer into
  /// the spec); empty when it conforms.
  [[nodiscard]] std::vector<std::string> schema_errors(const std::string& schema_location,
                                                       const nlohmann::json& instance) const {
    const valijson::Schema& schema = compiled(schema_location);
    valijson::Validator validator;  // strict types: "1" is not a number
    valijson::ValidationResults results;
    const nlohmann::json normalized = with_integral_numbers_as_integers(instance);
    const valijson::adapters::NlohmannJsonAdapter adapter(normalized);
    std::vector<std::string> errors;
    if (validator.validate(schema, adapter, &results)) return errors;
    valijson::ValidationResults::Error error;
    while (results.popError(error)) {
      std::string where;
      for (const auto& c : error.context) where += c;
      errors.push_back(where + ": " + error.description);
    }
    if (errors.empty()) errors.push_back("does not match " + schema_location);
    return errors;
  }

  /// The path template in the spec that `path` matches ("/playground/{file}"), or "".
  [[nodiscard]] std::string match_path(const std::string& path) const {
    const std::string plain = path.substr(0, path.find('?'));
    if (spec_.at("paths").contains(plain)) return plain;
    for (const auto& [name, item] : spec_.at("paths").items()) {
      if (template_matches(name, plain)) return name;
    }
    return "";
  }

  /// Every way `exchange` departs from the spec; empty when it conforms.
  [[nodiscard]] std::vector<std::string> violations(const HttpExchange& exchange) const {
    std::vector<std::string> out;
    const std::string where = exchange.method + " " + exchange.path + " -> " +
                              std::to_string(exchange.status) + ": ";
    const auto fail = [&](const std::string& message) { out.push_back(where + message); };
    const std::string path = match_path(exchange.path);
    std::string method;
    for (const char c : exchange.method) method += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool head = method == "head";
    std::string response_location;
    if (path.empty()) {
      // Paths not in the spec answer x-unlisted-paths-and-methods' 404 and nothing else.
      if (exchange.status != 404) fail("the path is not in the spec, so the answer must be 404");
      response_location = "/x-unlisted-paths-and-methods/responses/404";
    } else {
      const std::string item = "/paths/" + pointer_token(path);
      if (head && !at(item).contains("head") && at(item).contains("get")) method = "get";
      if (!at(item).contains(method)) {
        if (exchange.status != 405) fail("the spec has no " + exchange.method + " on " + path + ", so the answer must be 405");
        response_location = "/x-unlisted-paths-and-methods/responses/405";
      } else {
        const std::string operation = item + "/" + method;
        response_location = response_for(operation, exchange.status);
        if (response_location.empty()) {
          fail("status " + std::to_string(exchange.status) + " is not documented for this operation");
          return out;
        }
        if (exchange.status >= 200 && exchange.status < 300) {
          for (auto& e : request_violations(operation, exchange)) fail(e);
        }
      }
    }
    response_location = resolve(response_location);
    const nlohmann::json& response = at(response_location);
    if (exchange.headers_known && response.contains("headers")) {
      for (const auto& [name, header] : response.at("headers").items()) {
        std::string lower;
        for (const char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const auto& h = at(resolve(response_location + "/headers/" + pointer_token(name)));
        if (h.value("required", false) && !exchange.response_headers.contains(lower)) {
          fail("the documented header " + name + " is missing");
        }
      }
    }
    if (head) return out;  // no body to check
    if (!response.contains("content")) {
      if (!exchange.response_body.empty()) fail("the spec documents no body, but one was sent");
      return out;
    }
    const std::string media = media_type_of(exchange.response_content_type);
    if (!response.at("content").contains(media)) {
      fail("media type '" + exchange.response_content_type + "' is not documented (" +
           response.at("content").dump() + ")");
      return out;
    }
    const std::string media_location = response_location + "/content/" + pointer_token(media);
    if (is_json_media_type(media)) {
      const auto body = nlohmann::json::parse(exchange.response_body, nullptr, false);
      if (body.is_discarded()) {
        fail("the body is not JSON: " + exchange.response_body.substr(0, 200));
      } else if (at(media_location).contains("schema")) {
        for (auto& e : schema_errors(media_location + "/schema", body)) fail("response body " + e);
      }
    }
    return out;
  }

 private:
  static bool template_matches(const std::string& pattern, const std::string& path) {
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < pattern.size() && j < path.size()) {
      if (pattern[i] == '{') {
        const std::size_t close = pattern.find('}', i);
        if (close == std::string::npos) return false;
        const std::size_t end = path.find('/', j);
        const std::size_t segment_end = end == std::string::npos ? path.size() : end;
        if (segment_end == j) return false;  // a path parameter is never empty
        i = close + 1;
        j = segment_end;
      } else if (pattern[i++] != path[j++]) {
        return false;
      }
    }
    return i == pattern.size() && j == path.size();
  }

  /// The response documented for `status`: the exact code, then "4XX"-style ranges, then
  /// "default". "" when there is none.
  [[nodiscard]] std::string response_for(const std::string& operation, int status) const {
    const nlohmann::json& responses = at(operation + "/responses");
    const std::string code = std::to_string(status);
    for (const std::string& key : {code, code.substr(0, 1) + "XX", std::string("default")}) {
      if (responses.contains(key)) return operation + "/responses/" + key;
    }
    return "";
  }

  /// A request the service accepted must be one the spec allows.
  [[nodiscard]] std::vector<std::string> request_violations(const std::string& operation,
                                                            const HttpExchange& exchange) const {
    std::vector<std::string> out;
    if (!at(operation).contains("requestBody")) return out;
    const std::string body_location = resolve(operation + "/requestBody");
    const nlohmann::json& body_spec = at(body_location);
    if (exchange.request_body.empty()) {
      if (body_spec.value("required", false)) out.push_back("accepted a request without the required body");
      return out;
    }
    const std::string media = media_type_of(exchange.request_content_type);
    if (!body_spec.at("content").contains(media)) {
      out.push_back("accepted a request of undocumented media type '" + exchange.request_content_type + "'");
      return out;
    }
    const std::string media_location = body_location + "/content/" + pointer_token(media);
    auto body = nlohmann::json::parse(exchange.request_body, nullptr, false);
    if (exchange.path == "/batch" && exchange.status == 200) {
      // A batch answers an item its schema refuses in the item's place (BatchItem): the
      // items answered with a 4xx are left out, every other must be one the spec allows.
      const auto answer = nlohmann::json::parse(exchange.response_body, nullptr, false);
      if (body.is_object() && body.contains("requests") && body.at("requests").is_array() &&
          answer.is_object() && answer.contains("responses") &&
          answer.at("responses").size() == body.at("requests").size()) {
        nlohmann::json kept = nlohmann::json::array();
        for (std::size_t i = 0; i < body.at("requests").size(); ++i) {
          const int status = answer.at("responses").at(i).value("status", 0);
          if (status < 400 || status >= 500) kept.push_back(body.at("requests").at(i));
        }
        body["requests"] = std::move(kept);
      }
    }
    if (body.is_discarded()) {
      out.push_back("accepted a request body that is not JSON");
    } else if (at(media_location).contains("schema")) {
      for (auto& e : schema_errors(media_location + "/schema", body)) {
        out.push_back("accepted a request the spec forbids: " + e);
      }
    }
    return out;
  }

  /// The schema at `location`, parsed once. References inside it resolve against the
  /// whole spec: the schema is compiled as {"$ref": "#/target", "target": ..., "components": ...},
  /// read as draft 7 (as_draft7).
  [[nodiscard]] const valijson::Schema& compiled(const std::string& location) const {
    const std::lock_guard lock(mutex_);
    auto it = schemas_.find(location);
    if (it != schemas_.end()) return *it->second->schema;
    auto entry = std::make_unique<CompiledSchema>();
    entry->document = {{"$ref", "#/target"}, {"target", at(location)}};
    if (spec_.contains("components")) entry->document["components"] = spec_.at("components");
    entry->document = as_draft7(std::move(entry->document));
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    const valijson::adapters::NlohmannJsonAdapter adapter(entry->document);
    entry->schema = std::make_unique<valijson::Schema>();
    parser.populateSchema(adapter, *entry->schema);
    const valijson::Schema& schema = *entry->schema;
    schemas_.emplace(location, std::move(entry));
    return schema;
  }

  struct CompiledSchema {
    nlohmann::json document;
    std::unique_ptr<valijson::Schema> schema;
  };

  nlohmann::json spec_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::unique_ptr<CompiledSchema>> schemas_;
};

/// The contract of this repository: api/openapi.yaml, read once per test executable.
[[nodiscard]] inline const OpenApiContract& openapi_contract() {
  static const OpenApiContract contract(
      load_openapi_json(std::string(BEZIER_SOURCE_DIR) + "/api/openapi.yaml"));
  return contract;
}

/// A gtest failure for every way the exchange departs from api/openapi.yaml.
inline void expect_conforms(const HttpExchange& exchange) {
  for (const auto& v : openapi_contract().violations(exchange)) ADD_FAILURE() << "contract: " << v;
}

/// The same, from the pieces; `request_body` is sent as application/json when not empty.
inline void expect_conforms(const std::string& method, const std::string& path,
                            const std::string& request_body, int status,
                            const std::string& content_type, const std::string& response_body) {
  HttpExchange e;
  e.method = method;
  e.path = path;
  e.request_content_type = request_body.empty() ? "" : "application/json";
  e.request_body = request_body;
  e.status = status;
  e.response_content_type = content_type;
  e.response_body = response_body;
  expect_conforms(e);
}

/// From an httplib result, headers included (an unanswered request is a failure too).
inline void expect_conforms(const std::string& method, const std::string& path,
                            const std::string& request_content_type,
                            const std::string& request_body, const httplib::Result& result) {
  if (!result) {
    ADD_FAILURE() << "contract: " << method << " " << path << " got no answer";
    return;
  }
  HttpExchange e;
  e.method = method;
  e.path = path;
  e.request_content_type = request_content_type;
  e.request_body = request_body;
  e.status = result->status;
  e.response_content_type = result->get_header_value("Content-Type");
  e.response_body = result->body;
  e.headers_known = true;
  for (const auto& [name, value] : result->headers) {
    std::string lower;
    for (const char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    e.response_headers[lower] = value;
  }
  expect_conforms(e);
}

}  // namespace bezier::test

#pragma GCC diagnostic pop
