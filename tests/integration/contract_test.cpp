// The OpenAPI contract against the running service : api/openapi.yaml is
// served byte for byte; every example in it is sent and answered as documented; every
// constraint of every request schema, broken on purpose, is answered with the
// documented 4xx problem; and every answer, errors included, matches the spec's
// schemas (a status, media type or member the spec does not describe fails).
#include "tests/support/openapi_validator.hpp"  // first: see there

#include <httplib.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/handler.hpp"
#include "api/limits.hpp"
#include "core/intersect/options.hpp"
#include "core/intersect/result.hpp"
#include "tests/contract/schema_violations.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_suite.hpp"

namespace bezier::test {
namespace {

using nlohmann::json;

const OpenApiContract& contract() { return openapi_contract(); }

/// One HTTP request to the service, recorded as an exchange (headers included).
HttpExchange send(int port, const std::string& method, const std::string& path,
                  const std::string& content_type = "", const std::string& body = "",
                  const httplib::Headers& headers = {}) {
  httplib::Client client("127.0.0.1", port);
  client.set_read_timeout(30, 0);
  const char* type = content_type.empty() ? "application/json" : content_type.c_str();
  const httplib::Result r = [&] {
    if (method == "HEAD") return client.Head(path.c_str(), headers);
    if (method == "POST") return client.Post(path.c_str(), headers, body, type);
    if (method == "PUT") return client.Put(path.c_str(), headers, body, type);
    if (method == "PATCH") return client.Patch(path.c_str(), headers, body, type);
    if (method == "DELETE") return client.Delete(path.c_str(), headers);
    if (method == "OPTIONS") return client.Options(path.c_str(), headers);
    return client.Get(path.c_str(), headers);
  }();
  HttpExchange e;
  e.method = method;
  e.path = path;
  e.request_content_type = content_type;
  e.request_body = body;
  if (!r) {
    ADD_FAILURE() << method << " " << path << ": no answer";
    return e;
  }
  e.status = r->status;
  e.response_content_type = r->get_header_value("Content-Type");
  e.response_body = r->body;
  e.headers_known = true;
  for (const auto& [name, value] : r->headers) {
    std::string lower;
    for (const char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    e.response_headers[lower] = value;
  }
  return e;
}

/// The exchange of a raw request (one no client library sends) whose `answer` is the
/// service's bytes, head and body.
HttpExchange exchange_of_raw(const std::string& method, const std::string& path, const std::string& answer) {
  HttpExchange e;
  e.method = method;
  e.path = path;
  const std::size_t head_end = answer.find("\r\n\r\n");
  if (answer.size() < 12 || head_end == std::string::npos) {
    ADD_FAILURE() << method << " " << path << ": no complete answer: " << answer.substr(0, 300);
    return e;
  }
  e.status = status_of(answer);
  e.headers_known = true;
  for (std::size_t at = answer.find("\r\n"); at < head_end;) {
    const std::size_t next = answer.find("\r\n", at + 2);
    const std::string line = answer.substr(at + 2, next - at - 2);
    const std::size_t colon = line.find(':');
    std::string name;
    for (const char c : line.substr(0, colon)) name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::size_t value_at = line.find_first_not_of(' ', colon + 1);
    e.response_headers[name] = value_at == std::string::npos ? "" : line.substr(value_at);
    at = next;
  }
  e.response_content_type = e.response_headers["content-type"];
  e.response_body = body_of(answer);
  return e;
}

/// Sends and checks the answer against the spec.
HttpExchange exchange(int port, const std::string& method, const std::string& path,
                      const std::string& content_type = "", const std::string& body = "",
                      const httplib::Headers& headers = {}) {
  HttpExchange e = send(port, method, path, content_type, body, headers);
  SCOPED_TRACE(method + " " + path + " " + body.substr(0, 300));
  expect_conforms(e);
  return e;
}

/// "" when `actual` equals `expected` (numbers to 1e-12 relative to max(1, |expected|):
/// examples are written from closed forms, the service rounds; certified intervals are
/// narrower than that); else where they differ. Members named in `skip` (an example's
/// x-not-compared: values that depend on the run, such as search statistics) are not
/// compared; the schema still checks them.
std::string example_difference(const json& actual, const json& expected, const std::string& at = "",
                     const json& skip = json::array()) {
  if (expected.is_number() && actual.is_number()) {
    const double a = actual.get<double>();
    const double e = expected.get<double>();
    return std::fabs(a - e) <= 1e-12 * std::max(1.0, std::fabs(e)) ? "" : at + ": " + actual.dump() + " != " + expected.dump();
  }
  if (actual.type() != expected.type()) return at + ": " + actual.dump() + " != " + expected.dump();
  if (expected.is_array()) {
    if (actual.size() != expected.size()) return at + ": " + actual.dump() + " != " + expected.dump();
    for (std::size_t i = 0; i < expected.size(); ++i) {
      if (auto m = example_difference(actual[i], expected[i], at + "/" + std::to_string(i), skip); !m.empty()) return m;
    }
    return "";
  }
  if (expected.is_object()) {
    for (const auto& [k, v] : actual.items()) {
      if (!expected.contains(k)) return at + "/" + k + ": not in the example";
    }
    for (const auto& [k, v] : expected.items()) {
      if (!actual.contains(k)) return at + "/" + k + ": missing";
      if (std::find(skip.begin(), skip.end(), k) != skip.end()) continue;
      if (auto m = example_difference(actual.at(k), v, at + "/" + k, skip); !m.empty()) return m;
    }
    return "";
  }
  return actual == expected ? "" : at + ": " + actual.dump() + " != " + expected.dump();
}

struct Operation {
  std::string path;
  std::string method;  // lower case, as in the spec
  std::string location;
};

std::vector<Operation> operations() {
  std::vector<Operation> out;
  for (const auto& [path, item] : contract().spec().at("paths").items()) {
    for (const char* m : {"get", "post", "put", "patch", "delete"}) {
      if (item.contains(m)) out.push_back({path, m, "/paths/" + pointer_token(path) + "/" + m});
    }
  }
  return out;
}

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// The concrete path of an operation: path parameters take their documented example.
std::string concrete_path(const Operation& op) {
  std::string path = op.path;
  const json& node = contract().at(op.location);
  for (const auto& p : member_or_empty(node, "parameters")) {
    const json& param = p.contains("$ref") ? contract().at(p.at("$ref").get<std::string>()) : p;
    if (param.at("in") != "path") continue;
    EXPECT_TRUE(param.contains("example")) << op.path << ": path parameter without an example";
    std::string name = "{";
    name += param.at("name").get<std::string>();
    name += "}";
    if (const auto at = path.find(name); at != std::string::npos) path.replace(at, name.size(), param.value("example", "x"));
  }
  return path;
}

/// Where the request schema of an operation is, or "" when it takes no body.
std::string request_schema(const Operation& op) {
  const json& node = contract().at(op.location);
  if (!node.contains("requestBody")) return "";
  return contract().resolve(op.location + "/requestBody") + "/content/application~1json/schema";
}

/// The response example called `name` of an operation: {status, location of the example}.
std::pair<int, std::string> response_example(const Operation& op, const std::string& name) {
  for (const auto& [status, ref] : contract().at(op.location + "/responses").items()) {
    const std::string response = contract().resolve(op.location + "/responses/" + status);
    for (const auto& [media, content] : member_or_empty(contract().at(response), "content").items()) {
      if (content.contains("examples") && content.at("examples").contains(name)) {
        return {std::stoi(status), response + "/content/" + pointer_token(media) + "/examples/" + name};
      }
    }
  }
  return {0, ""};
}

/// A batch answers an item its schema refuses in the item's place (BatchItem): for a
/// request to /batch, the index of the item that every pointer lies in, at its `path` or
/// inside its `body`; nullopt when some pointer lies elsewhere (the batch itself is refused).
std::optional<std::size_t> batch_item_of(const std::vector<std::string>& pointers) {
  std::optional<std::size_t> item;
  for (const std::string& p : pointers) {
    const std::string prefix = "/requests/";
    if (p.rfind(prefix, 0) != 0) return std::nullopt;
    const std::size_t end = p.find('/', prefix.size());
    if (end == std::string::npos) return std::nullopt;
    const std::string index = p.substr(prefix.size(), end - prefix.size());
    if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    const std::string member = p.substr(end);
    if (member != "/path" && member != "/body" && member.rfind("/body/", 0) != 0) return std::nullopt;
    const std::size_t i = std::stoul(index);
    if (item && *item != i) return std::nullopt;
    item = i;
  }
  return item;
}

/// Whether a constraint site of /batch is one its examples need not break: those in an
/// item's body (the route's own request schema, whose every constraint that route's
/// examples break), and those of each member of BatchItem on the item and its `path` (the
/// same constraints in every member, one route's name apart, broken in the members the
/// examples use).
bool exercised_elsewhere(const Operation& op, const std::string& site) {
  if (op.path != "/batch") return false;
  const std::string members = " @ /components/schemas/BatchItem/oneOf/";
  return site.rfind("/requests/*/body", 0) == 0 || site.rfind("/requests/*" + members, 0) == 0 ||
         site.rfind("/requests/*/path" + members, 0) == 0;
}

class ContractTest : public ServiceSuite<ContractTest> {
 public:
  // The service runs with its default limits: the spec's bounds are those defaults.
  static std::vector<std::string> service_args() { return {}; }
};

TEST_F(ContractTest, TheServedSpecIsTheFile) {
  const auto e = exchange(port(), "GET", "/openapi.yaml");
  std::ifstream file(std::string(BEZIER_SOURCE_DIR) + "/api/openapi.yaml", std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_TRUE(e.response_body == text.str())
      << "GET /openapi.yaml (" << e.response_body.size() << " bytes) is not api/openapi.yaml ("
      << text.str().size() << " bytes): rebuild the service";
  EXPECT_EQ(contract().spec().at("openapi"), "3.1.0");
}

TEST_F(ContractTest, TheServedJsonIsTheSpec) {
  // The JSON is the YAML's content: equal as documents to the file read independently of
  // the build (the same converter, run now on the source).
  const auto e = exchange(port(), "GET", "/openapi.json");
  EXPECT_EQ(e.status, 200);
  const json served = json::parse(e.response_body);
  EXPECT_TRUE(served == contract().spec()) << "GET /openapi.json is not api/openapi.yaml's content: rebuild the service";
  EXPECT_EQ(served.at("paths").size(), contract().spec().at("paths").size());
}

TEST_F(ContractTest, EveryRouteOfTheServiceIsInTheSpec) {
  std::set<std::string> documented;
  for (const Operation& op : operations()) {
    if (op.method == "post") documented.insert(op.path);
  }
  std::set<std::string> served;
  for (const std::string_view route : api::post_routes()) served.emplace(route);
  EXPECT_EQ(served, documented) << "POST routes of the service (api/handler.cpp) vs the spec's";
}

TEST_F(ContractTest, TheDescriptionListsEveryRoute) {
  // info.description's "## Routes": one line per route, the POST routes in the registry's
  // order (api/route_table.hpp, then /batch), then every GET route of the spec.
  const std::string description = contract().spec().at("info").at("description").get<std::string>();
  const std::size_t start = description.find("## Routes\n");
  ASSERT_NE(start, std::string::npos) << "info.description has no \"## Routes\" section";
  const std::size_t end = description.find("\n## ", start + 1);
  std::istringstream lines(description.substr(start, end - start));
  std::vector<std::string> posts;
  std::set<std::string> gets;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("- `", 0) != 0) continue;
    // Every `METHOD /path` before the line's colon.
    const std::string names = line.substr(0, line.find("`: ") + 1);
    for (std::size_t open = names.find('`'); open != std::string::npos;) {
      const std::size_t close = names.find('`', open + 1);
      if (close == std::string::npos) break;
      const std::string name = names.substr(open + 1, close - open - 1);
      if (name.rfind("POST ", 0) == 0) posts.push_back(name.substr(5));
      if (name.rfind("GET ", 0) == 0) gets.insert(name.substr(4));
      open = names.find('`', close + 1);
    }
  }
  const std::vector<std::string> registry(api::post_routes().begin(), api::post_routes().end());
  EXPECT_EQ(posts, registry) << "the POST routes of info.description vs api::post_routes()";
  std::set<std::string> documented;
  for (const Operation& op : operations()) {
    if (op.method == "get") documented.insert(op.path);
  }
  EXPECT_EQ(gets, documented) << "the GET routes of info.description vs the spec's";
}

TEST_F(ContractTest, EveryComputeRouteIsABatchItem) {
  // BatchItem: one member per compute route, in the registry's order, whose body is the
  // route's own request schema.
  const json& members = contract().at("/components/schemas/BatchItem").at("oneOf");
  const auto routes = api::batch_item_routes();
  ASSERT_EQ(members.size(), routes.size());
  for (std::size_t i = 0; i < routes.size(); ++i) {
    const std::string route(routes[i]);
    SCOPED_TRACE(route);
    const json& member = contract().at(contract().resolve("/components/schemas/BatchItem/oneOf/" + std::to_string(i)));
    EXPECT_EQ(member.at("properties").at("path").at("const"), route);
    const json& body = contract().at("/paths/" + pointer_token(route) + "/post/requestBody/content/application~1json/schema");
    EXPECT_EQ(member.at("properties").at("body"), body);
  }
}

TEST_F(ContractTest, TheSpecStatesTheServiceDefaults) {
  const api::Limits defaults;
  const json& limits = contract().spec().at("info").at("x-limits");
  EXPECT_EQ(limits.at("max_degree"), defaults.max_degree);
  EXPECT_EQ(limits.at("max_t_values"), defaults.max_t_values);
  EXPECT_EQ(limits.at("max_path_segments"), defaults.max_path_segments);
  EXPECT_EQ(limits.at("max_body_bytes"), defaults.max_body_bytes);
  EXPECT_EQ(limits.at("max_work"), defaults.max_work);
  EXPECT_EQ(limits.at("max_batch_items"), defaults.max_batch_items);
  EXPECT_EQ(limits.at("max_batch_work"), defaults.max_batch_work);
  EXPECT_EQ(limits.at("max_batch_answer_bytes"), defaults.max_batch_answer_bytes);
  const auto schema = [](const std::string& name) -> const json& { return contract().at("/components/schemas/" + name); };
  EXPECT_EQ(schema("Points2").at("maxItems"), defaults.max_degree + 1);
  EXPECT_EQ(schema("Points3").at("maxItems"), defaults.max_degree + 1);
  EXPECT_EQ(schema("Parameters").at("oneOf").at(1).at("maxItems"), defaults.max_t_values);
  EXPECT_EQ(schema("Samples").at("maximum"), defaults.max_t_values);
  EXPECT_EQ(schema("BatchRequest").at("properties").at("requests").at("maxItems"), defaults.max_batch_items);
  EXPECT_EQ(schema("Derivatives").at("maximum"), defaults.max_degree);
  EXPECT_EQ(schema("PolarArguments").at("oneOf").at(1).at("maxItems"), defaults.max_degree);
  const core::IntersectOptions intersect;
  const json& options = schema("IntersectionsRequest").at("properties");
  EXPECT_EQ(options.at("tolerance").at("minimum").get<double>(), core::kMinTolerance);
  // Defaults are in x-default (JSON Schema's `default` makes generated request types
  // require the member).
  EXPECT_EQ(options.at("tolerance").at("x-default").get<double>(), intersect.tolerance);
  EXPECT_EQ(options.at("method").at("x-default"), core::to_string(intersect.method));
  EXPECT_EQ(options.at("fat_curve_degree").at("x-default"), intersect.fat_curve_degree);
}

TEST_F(ContractTest, ExamplesMatchTheirOwnSchemas) {
  for (const Operation& op : operations()) {
    SCOPED_TRACE(op.method + " " + op.path);
    if (const std::string schema = request_schema(op); !schema.empty()) {
      const std::string media = contract().resolve(op.location + "/requestBody") + "/content/application~1json";
      for (const auto& [name, example] : member_or_empty(contract().at(media), "examples").items()) {
        for (const auto& e : contract().schema_errors(schema, example.at("value"))) ADD_FAILURE() << name << ": " << e;
      }
    }
    for (const auto& [status, ref] : contract().at(op.location + "/responses").items()) {
      const std::string response = contract().resolve(op.location + "/responses/" + status);
      for (const auto& [media, content] : member_or_empty(contract().at(response), "content").items()) {
        for (const auto& [name, example] : member_or_empty(content, "examples").items()) {
          const std::string schema = response + "/content/" + pointer_token(media) + "/schema";
          for (const auto& e : contract().schema_errors(schema, example.at("value"))) {
            ADD_FAILURE() << status << " " << name << ": " << e;
          }
        }
      }
    }
  }
}

TEST_F(ContractTest, EveryExampleIsAnsweredAsDocumented) {
  for (const Operation& op : operations()) {
    SCOPED_TRACE(op.method + " " + op.path);
    const std::string path = concrete_path(op);
    int answered = 0;
    if (request_schema(op).empty()) {
      // No request body: one request, and every 200 example must be its answer.
      const auto e = exchange(port(), upper(op.method), path);
      EXPECT_EQ(e.status, 200) << e.response_body;
      const std::string ok = contract().resolve(op.location + "/responses/200");
      for (const auto& [media, content] : member_or_empty(contract().at(ok), "content").items()) {
        for (const auto& [name, example] : member_or_empty(content, "examples").items()) {
          EXPECT_EQ(example_difference(json::parse(e.response_body, nullptr, false), example.at("value"), "",
                             member_or_empty(example, "x-not-compared")), "") << name;
        }
      }
      answered += e.status == 200;
      EXPECT_EQ(exchange(port(), "HEAD", path).status, 200);
    } else {
      // Every request example (valid or x-invalid-request-examples) is answered by the
      // response example of the same name.
      const std::string media = contract().resolve(op.location + "/requestBody") + "/content/application~1json";
      json examples = json::object();
      for (const json* group : {&member_or_empty(contract().at(media), "examples"),
                                &member_or_empty(contract().at(op.location), "x-invalid-request-examples")}) {
        if (group->is_object()) examples.update(*group);
      }
      for (const auto& [name, example] : examples.items()) {
        SCOPED_TRACE("example " + name);
        const auto [status, where] = response_example(op, name);
        ASSERT_NE(status, 0) << "no response example named " << name;
        const auto e = exchange(port(), "POST", path, "application/json", example.at("value").dump());
        EXPECT_EQ(e.status, status) << e.response_body;
        const json& shown = contract().at(where);
        EXPECT_EQ(example_difference(json::parse(e.response_body, nullptr, false), shown.at("value"), "",
                           member_or_empty(shown, "x-not-compared")), "");
        answered += e.status >= 200 && e.status < 300;
      }
      // No response example without its request: one of the same name above, or the raw
      // body in its x-request-body (for shared responses such as MalformedJson).
      for (const auto& [status, ref] : contract().at(op.location + "/responses").items()) {
        const std::string response = contract().resolve(op.location + "/responses/" + status);
        for (const auto& [type, content] : member_or_empty(contract().at(response), "content").items()) {
          for (const auto& [name, example] : member_or_empty(content, "examples").items()) {
            if (examples.contains(name)) continue;
            SCOPED_TRACE("response example " + name);
            ASSERT_TRUE(example.contains("x-request-body")) << "no request gives this example";
            const auto e = exchange(port(), "POST", path, "application/json", example.at("x-request-body").get<std::string>());
            EXPECT_EQ(e.status, std::stoi(status)) << e.response_body;
            EXPECT_EQ(example_difference(json::parse(e.response_body, nullptr, false), example.at("value"), "",
                               member_or_empty(example, "x-not-compared")), "");
          }
        }
      }
    }
    EXPECT_GE(answered, 1) << "no example of a successful call";
  }
}

/// Calls f(op, schema, examples) for each operation with a JSON request body: its request
/// schema and the examples of that body, inside a trace that names the operation.
template <class F>
void for_each_request_body(const F& f) {
  for (const Operation& op : operations()) {
    const std::string schema = request_schema(op);
    if (schema.empty()) continue;
    SCOPED_TRACE(op.method + " " + op.path);
    const std::string media = contract().resolve(op.location + "/requestBody") + "/content/application~1json";
    f(op, schema, contract().at(media).at("examples"));
  }
}

TEST_F(ContractTest, EveryRequestConstraintIsEnforced) {
  const ViolationGenerator generator(contract());
  for_each_request_body([&](const Operation& op, const std::string& schema, const json& examples) {
    std::set<std::string> uncovered = generator.sites(schema);
    std::map<std::string, SchemaViolation> crossings;
    int sent = 0;
    for (const auto& [name, example] : examples.items()) {
      for (SchemaViolation& c : generator.crossings(schema, example.at("value"))) {
        c.what = name + ": " + c.what;
        crossings.emplace(c.site, std::move(c));
      }
      for (const SchemaViolation& v : generator.violations(schema, example.at("value"))) {
        SCOPED_TRACE(name + ": " + v.what + " (" + v.site + "): " + v.request.dump().substr(0, 300));
        const auto e = exchange(port(), "POST", op.path, "application/json", v.request.dump());
        uncovered.erase(v.site);
        ++sent;
        std::vector<std::string> pointers = v.pointers;
        json problem = json::parse(e.response_body, nullptr, false);
        bool whole_body = !v.request.is_object();  // not an object: the route's 400
        if (const auto item = batch_item_of(pointers); op.path == "/batch" && item && e.status == 200) {
          // Refused in the item's place: a 4xx item (404 for a path that names no compute
          // route), whose errors point into the item's body.
          ASSERT_LT(*item, problem.at("responses").size()) << e.response_body;
          const json& answer = problem.at("responses").at(*item);
          const int status = answer.at("status").get<int>();
          EXPECT_TRUE(status >= 400 && status < 500) << "item " << *item << ": " << answer.dump().substr(0, 300);
          if (v.site.rfind("/requests/*/path ", 0) == 0) {
            EXPECT_EQ(status, 404) << answer.dump().substr(0, 300);
            continue;
          }
          const std::string body = "/requests/" + std::to_string(*item) + "/body";
          std::vector<std::string> inside;
          for (const std::string& p : pointers) {
            if (p.rfind(body, 0) == 0) inside.push_back(p.substr(body.size()));
          }
          pointers = inside;
          problem = answer.at("body");
          whole_body = !v.request.at(json::json_pointer(body)).is_object();
          EXPECT_EQ(status, whole_body ? 400 : 422) << answer.dump().substr(0, 300);
          if (whole_body || status != 422 || !problem.contains("errors")) continue;
        } else {
          EXPECT_EQ(e.status, whole_body ? 400 : 422) << e.response_body;
          if (whole_body || e.status != 422 || !problem.contains("errors")) continue;
        }
        EXPECT_EQ(problem.at("type"), "urn:bezier-service:problem:validation");
        // Some error points at what was broken: the same member, one inside or around it,
        // or a sibling in the same array (a point that is ragged against the others).
        const auto related = [&](const std::string& p) {
          for (const auto& q : pointers) {
            const auto parent = [](const std::string& s) { return s.substr(0, s.rfind('/')); };
            if (p == q || p.rfind(q + "/", 0) == 0 || q.rfind(p + "/", 0) == 0 ||
                (!parent(p).empty() && parent(p) == parent(q))) {
              return true;
            }
          }
          return false;
        };
        bool found = false;
        for (const auto& err : problem.at("errors")) found = found || related(err.at("pointer").get<std::string>());
        EXPECT_TRUE(found) << "no error points at " << json(pointers).dump() << ": " << problem.dump().substr(0, 600);
      }
    }
    // A constraint that tells one shape of the request from another: broken, the request
    // has the other shape, which the service must take.
    for (auto it = uncovered.begin(); it != uncovered.end();) {
      const auto crossing = crossings.find(*it);
      if (crossing == crossings.end()) {
        ++it;
        continue;
      }
      const SchemaViolation& c = crossing->second;
      SCOPED_TRACE(c.what + " (" + c.site + "), another shape: " + c.request.dump().substr(0, 300));
      EXPECT_EQ(exchange(port(), "POST", op.path, "application/json", c.request.dump()).status, 200);
      ++sent;
      it = uncovered.erase(it);
    }
    for (const auto& site : uncovered) {
      if (!exercised_elsewhere(op, site)) ADD_FAILURE() << "no request example lets the test break " << site;
    }
    std::printf("%s %s: %d requests, each breaking one of %zu constraints\n", upper(op.method).c_str(),
                op.path.c_str(), sent, generator.sites(schema).size());
  });
}

TEST_F(ContractTest, EveryBoundIsAccepted) {
  const ViolationGenerator generator(contract());
  for_each_request_body([&](const Operation& op, const std::string& schema, const json& examples) {
    std::set<std::string> unreached = generator.bound_sites(schema);
    std::map<std::string, std::string> refusals;
    for (const auto& [name, example] : examples.items()) {
      for (const SchemaViolation& b : generator.boundaries(schema, example.at("value"))) {
        const auto e = exchange(port(), "POST", op.path, "application/json", b.request.dump());
        if (e.status == 200) {
          unreached.erase(b.site);
        } else {
          refusals[b.site] = name + ": " + b.what + " -> " + std::to_string(e.status) + " " + e.response_body.substr(0, 300);
        }
      }
    }
    // A bound the service refuses from every example is a spec looser than the service
    // (or an example missing: each bound needs one example from which it is reachable).
    for (const auto& site : unreached) {
      if (!exercised_elsewhere(op, site)) ADD_FAILURE() << "no example reaches the bound " << site << ": " << refusals[site];
    }
  });
}

TEST_F(ContractTest, ErrorsOutsideTheSchemasAreDocumented) {
  for (const Operation& op : operations()) {
    SCOPED_TRACE(op.method + " " + op.path);
    const std::string path = concrete_path(op);
    if (op.method == "post") {
      EXPECT_EQ(exchange(port(), "POST", path, "application/json", "{\"points\": [[0,0],").status, 400);
      EXPECT_EQ(exchange(port(), "POST", path, "application/json", "[1, 2]").status, 400);
      EXPECT_EQ(exchange(port(), "POST", path, "application/json", "").status, 400);
      EXPECT_EQ(exchange(port(), "POST", path, "text/plain", "{}").status, 415);
      const std::string huge = "{\"pad\": \"" + std::string(api::Limits{}.max_body_bytes, 'x') + "\"}";
      EXPECT_EQ(exchange(port(), "POST", path, "application/json", huge).status, 413);
      // A non-finite number is a field error, with its pointer.
      EXPECT_EQ(exchange(port(), "POST", path, "application/json", "{\"points\": [[0, 1e999]]}").status, 422);
      for (const char* m : {"GET", "HEAD", "PUT", "PATCH", "DELETE", "OPTIONS"}) {
        EXPECT_EQ(exchange(port(), m, path, "application/json", "{}").status, 405) << m;
      }
    } else {
      for (const char* m : {"POST", "PUT", "PATCH", "DELETE", "OPTIONS"}) {
        EXPECT_EQ(exchange(port(), m, path, "application/json", "{}").status, 405) << m;
      }
    }
  }
  EXPECT_EQ(exchange(port(), "GET", "/no-such-route").status, 404);
  EXPECT_EQ(exchange(port(), "POST", "/no-such-route", "application/json", "{}").status, 404);
  EXPECT_EQ(exchange(port(), "GET", "/playground/no-such-file.html").status, 404);
}

TEST_F(ContractTest, AnswersOfTheHttpLayerAreDocumented) {
  // Requests that are not valid HTTP/1.1, or too large, to every operation: each answer
  // is a status the operation declares, with the documented body and headers.
  for (const Operation& op : operations()) {
    const std::string method = upper(op.method);
    const std::string path = concrete_path(op);
    const std::string line = method + " " + path;
    const std::string pad(api::Limits{}.max_body_bytes / 64, 'a');  // beyond the 16 KiB head limit
    const std::vector<std::pair<int, std::string>> requests = {
        {400, line + " HTTP/1.1\r\nHost: x\r\nno colon in this header line\r\n\r\n"},
        {413, line + " HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: " +
                  std::to_string(api::Limits{}.max_body_bytes + 1) + "\r\n\r\n"},
        {414, line + "?" + pad + " HTTP/1.1\r\nHost: x\r\n\r\n"},
        {431, line + " HTTP/1.1\r\nHost: x\r\nX-Pad: " + pad + "\r\n\r\n"},
        {501, line + " HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: gzip\r\n\r\n"},
        {505, line + " HTTP/2.0\r\nHost: x\r\n\r\n"},
    };
    for (const auto& [status, bytes] : requests) {
      SCOPED_TRACE(line + ", expecting " + std::to_string(status));
      const HttpExchange e = exchange_of_raw(method, path, round_trip(port(), bytes));
      EXPECT_EQ(e.status, status) << e.response_body;
      expect_conforms(e);
    }
  }
}

TEST(ContractOfSlowRequests, RequestTimeoutIsDocumented) {
  ServiceProcess service({"--read-timeout", "1"});
  for (const auto& [method, path, bytes] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"GET", "/healthz", "GET /healthz HTTP/1.1\r\nHost: x\r\n"},
           {"POST", "/evaluate",
            "POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 40\r\n\r\n{"}}) {
    SCOPED_TRACE(method + " " + path);
    const HttpExchange e = exchange_of_raw(method, path, round_trip(service.port(), bytes));
    EXPECT_EQ(e.status, 408) << e.response_body;
    expect_conforms(e);
  }
}

TEST(ContractAtTheConnectionLimit, OverloadedIsDocumented) {
  ServiceProcess service({"--max-connections", "1", "--io-threads", "1"});
  Connection held(service.port());
  ASSERT_TRUE(held.send_all(get_request("/healthz")));
  ASSERT_EQ(held.responses(1).size(), 1u);
  for (const Operation& op : operations()) {
    SCOPED_TRACE(op.method + " " + op.path);
    // The answer comes before any request is read: the connection is refused at once.
    Connection refused(service.port());
    const auto answers = refused.responses(1);
    ASSERT_EQ(answers.size(), 1u);
    const HttpExchange e = exchange_of_raw(upper(op.method), concrete_path(op), answers[0]);
    EXPECT_EQ(e.status, 503) << e.response_body;
    expect_conforms(e);
  }
}

TEST(ContractWithToken, UnauthorizedIsDocumented) {
  ServiceProcess service({}, {"BEZIER_AUTH_TOKEN=contract-secret"});
  for (const Operation& op : operations()) {
    if (op.method != "post") continue;
    const json& examples = contract().at(contract().resolve(op.location + "/requestBody") + "/content/application~1json/examples");
    const std::string body = examples.begin()->at("value").dump();
    EXPECT_EQ(exchange(service.port(), "POST", op.path, "application/json", body).status, 401) << op.path;
    EXPECT_EQ(exchange(service.port(), "POST", op.path, "application/json", body,
                       {{"Authorization", "Bearer contract-secret"}}).status, 200) << op.path;
  }
}

TEST(ContractWhileDraining, NotReadyIsDocumented) {
  ServiceProcess service({"--drain-seconds", "2"});
  EXPECT_EQ(exchange(service.port(), "GET", "/readyz").status, 200);
  service.signal(SIGTERM);
  int status = 200;
  for (int i = 0; i < 100 && status == 200; ++i) {
    status = send(service.port(), "GET", "/readyz").status;
    if (status == 200) usleep(10000);
  }
  EXPECT_EQ(exchange(service.port(), "GET", "/readyz").status, 503);
  EXPECT_EQ(exchange(service.port(), "GET", "/healthz").status, 200);
  EXPECT_EQ(service.wait_exit(), std::optional<int>(0));
}

}  // namespace
}  // namespace bezier::test
