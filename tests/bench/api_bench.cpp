// The request -> answer path without sockets: api::handle on the bodies that
// tests/bench/http/compare_peer.sh sends with wrk, so the HTTP figures can be split into
// what the socket layer costs and what parsing, the kernel and the JSON answer cost.
// The bodies are byte for byte the peer service's wrk bodies (compare_peer.sh says what the
// peer is; its own benchmark bodies: one cubic with t = 0.5, the first intersecting random cubic
// pair of the peer's generator, one cubic to classify), plus /healthz-sized work for reference:
// parsing an empty object.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter='ApiHandle|ParseJson'
//
// ParseJson_*: a body parsed into a document and freed again, by api::parse_json and by
// nlohmann's own parser (its DOM parse is sax_parse with nlohmann's document-building
// handler), and nlohmann's sax_parse with a handler that keeps nothing: the least any SAX
// design on nlohmann, building the request structures directly included, could cost.
// With -DBEZIER_BENCH_SIMDJSON (libsimdjson-dev; not part of the build), simdjson's
// On-Demand parser building the same document too (BENCHMARKS.md, "JSON reading and
// writing", has the command).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/handler.hpp"
#include "api/parse_json.hpp"

#ifdef BEZIER_BENCH_SIMDJSON
#include <simdjson.h>
#endif

namespace {

constexpr std::string_view kEvaluate =
    R"({"points":[[0.62707394058816135,0.0027357211802154779],[0.52744703995995224,0.98105096747167408],[0.96837789821438491,0.28110350295901299],[0.61283886060118675,0.7207431411370635]],"t":0.5})";
constexpr std::string_view kClassify =
    R"({"points":[[0.62707394058816135,0.0027357211802154779],[0.52744703995995224,0.98105096747167408],[0.96837789821438491,0.28110350295901299],[0.61283886060118675,0.7207431411370635]]})";
constexpr std::string_view kIntersections =
    R"({"curves":[{"points":[[0.6575514690484852,0.5090645046439022],[0.5315440169069916,0.07611245918087661],[0.8079907614737749,0.8542386966291815],[0.2727865446358919,0.1642689702566713]]},{"points":[[0.30325650586746633,0.8939741610083729],[0.2899394116830081,0.14372913632541895],[0.6545765674673021,0.5490608897525817],[0.32461709063500166,0.12016563094221056]]}]})";

void run(benchmark::State& state, std::string_view path, std::string_view body) {
  const bezier::api::Limits limits;
  int status = 0;
  for (auto _ : state) {
    const bezier::api::Reply reply = bezier::api::handle(path, body, limits);
    status = reply.status;
    benchmark::DoNotOptimize(reply.body.data());
  }
  state.counters["status"] = status;
}

void BM_ApiHandle_Evaluate(benchmark::State& state) { run(state, "/evaluate", kEvaluate); }
void BM_ApiHandle_Intersections(benchmark::State& state) { run(state, "/intersections", kIntersections); }
void BM_ApiHandle_Classify(benchmark::State& state) { run(state, "/classify", kClassify); }
// A body every route rejects after parsing (422, missing fields): parsing and the problem
// answer alone.
void BM_ApiHandle_EmptyObject(benchmark::State& state) { run(state, "/evaluate", "{}"); }
BENCHMARK(BM_ApiHandle_Evaluate);
BENCHMARK(BM_ApiHandle_Intersections);
BENCHMARK(BM_ApiHandle_Classify);
BENCHMARK(BM_ApiHandle_EmptyObject);

template <class Parse>
void parse(benchmark::State& state, std::string_view body, Parse parse_body) {
  for (auto _ : state) {
    nlohmann::json document = parse_body(body);
    benchmark::DoNotOptimize(document.size());
  }
}

nlohmann::json own_parser(std::string_view body) { return bezier::api::parse_json(body).value; }

nlohmann::json nlohmann_parser(std::string_view body) {
  return nlohmann::json::parse(body.begin(), body.end(), nullptr, /*allow_exceptions=*/false);
}

// Every event accepted and dropped: nlohmann's lexer and parser alone.
struct DiscardingHandler {
  using json = nlohmann::json;
  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t) { return true; }
  bool number_float(json::number_float_t, const std::string&) { return true; }
  bool string(std::string&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool start_object(std::size_t) { return true; }
  bool key(std::string&) { return true; }
  bool end_object() { return true; }
  bool start_array(std::size_t) { return true; }
  bool end_array() { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }
};

nlohmann::json nlohmann_sax_discarding(std::string_view body) {
  DiscardingHandler handler;
  return nlohmann::json::sax_parse(body.begin(), body.end(), &handler);
}

void BM_ParseJson_Own_Evaluate(benchmark::State& state) { parse(state, kEvaluate, own_parser); }
void BM_ParseJson_Own_Intersections(benchmark::State& state) { parse(state, kIntersections, own_parser); }
void BM_ParseJson_Nlohmann_Evaluate(benchmark::State& state) { parse(state, kEvaluate, nlohmann_parser); }
void BM_ParseJson_Nlohmann_Intersections(benchmark::State& state) {
  parse(state, kIntersections, nlohmann_parser);
}
void BM_ParseJson_NlohmannSaxDiscarding_Evaluate(benchmark::State& state) {
  parse(state, kEvaluate, nlohmann_sax_discarding);
}
void BM_ParseJson_NlohmannSaxDiscarding_Intersections(benchmark::State& state) {
  parse(state, kIntersections, nlohmann_sax_discarding);
}
BENCHMARK(BM_ParseJson_Own_Evaluate);
BENCHMARK(BM_ParseJson_Own_Intersections);
BENCHMARK(BM_ParseJson_Nlohmann_Evaluate);
BENCHMARK(BM_ParseJson_Nlohmann_Intersections);
BENCHMARK(BM_ParseJson_NlohmannSaxDiscarding_Evaluate);
BENCHMARK(BM_ParseJson_NlohmannSaxDiscarding_Intersections);

#ifdef BEZIER_BENCH_SIMDJSON
// The valid bodies only: what an error costs, or reports, is not measured here.
namespace ondemand = simdjson::ondemand;

simdjson::error_code build(ondemand::value value, nlohmann::json& out) {
  ondemand::json_type type;
  if (auto e = value.type().get(type)) return e;
  switch (type) {
    case ondemand::json_type::object: {
      out = nlohmann::json::object();
      ondemand::object object;
      if (auto e = value.get_object().get(object)) return e;
      for (auto field : object) {
        std::string_view key;
        if (auto e = field.unescaped_key().get(key)) return e;
        if (auto e = build(field.value(), out[std::string(key)])) return e;
      }
      return simdjson::SUCCESS;
    }
    case ondemand::json_type::array: {
      out = nlohmann::json::array();
      ondemand::array array;
      if (auto e = value.get_array().get(array)) return e;
      for (auto element : array) {
        ondemand::value v;
        if (auto e = element.get(v)) return e;
        out.push_back(nullptr);
        if (auto e = build(v, out.back())) return e;
      }
      return simdjson::SUCCESS;
    }
    case ondemand::json_type::number: {
      ondemand::number_type kind;
      if (auto e = value.get_number_type().get(kind)) return e;
      if (kind == ondemand::number_type::unsigned_integer) {
        std::uint64_t u = 0;
        if (auto e = value.get_uint64().get(u)) return e;
        out = u;
      } else if (kind == ondemand::number_type::signed_integer) {
        std::int64_t i = 0;
        if (auto e = value.get_int64().get(i)) return e;
        out = i;
      } else {
        double d = 0.0;
        if (auto e = value.get_double().get(d)) return e;
        out = d;
      }
      return simdjson::SUCCESS;
    }
    case ondemand::json_type::string: {
      std::string_view text;
      if (auto e = value.get_string().get(text)) return e;
      out = std::string(text);
      return simdjson::SUCCESS;
    }
    case ondemand::json_type::boolean: {
      bool flag = false;
      if (auto e = value.get_bool().get(flag)) return e;
      out = flag;
      return simdjson::SUCCESS;
    }
    case ondemand::json_type::null: out = nullptr; return simdjson::SUCCESS;
  }
  return simdjson::TAPE_ERROR;
}

// As a service would call it: one parser and one padded copy of the body per thread.
nlohmann::json simdjson_parser(std::string_view body) {
  thread_local ondemand::parser parser;
  thread_local std::string padded;
  padded.assign(body);
  padded.append(simdjson::SIMDJSON_PADDING, ' ');
  nlohmann::json out;
  ondemand::document document;
  ondemand::value root;
  if (parser.iterate(padded.data(), body.size(), padded.size()).get(document) ||
      document.get_value().get(root) || build(root, out)) {
    return nlohmann::json(nlohmann::json::value_t::discarded);
  }
  return out;
}

void BM_ParseJson_SimdjsonOnDemand_Evaluate(benchmark::State& state) { parse(state, kEvaluate, simdjson_parser); }
void BM_ParseJson_SimdjsonOnDemand_Intersections(benchmark::State& state) {
  parse(state, kIntersections, simdjson_parser);
}
BENCHMARK(BM_ParseJson_SimdjsonOnDemand_Evaluate);
BENCHMARK(BM_ParseJson_SimdjsonOnDemand_Intersections);
#endif

}  // namespace
