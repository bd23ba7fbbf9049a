// libFuzzer target: the request -> response path of the POST routes on requests of the
// right shape. Bodies made of random bytes rarely get past the JSON parser and the
// validation (api_request_fuzzer covers those); this target builds each route's request
// object from the bytes instead (points, parameters, options, with numbers chosen to be
// degenerate, extreme or a few ulps apart, see NumberSource), so the kernels behind the
// routes run on every input.
//
// Input: byte 0 picks the route (bits 0-2, modulo the five routes) and the limits (bit
// 3: defaults, or tight ones); the rest feeds the request builder. Checks: everything in
// reply_checks.hpp; never 400 (the body is always an object); and when the builder kept
// every field within the documented rules, 200, the work-cap 422 or the 422 for a result
// beyond the double range, nothing else.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "api/handler.hpp"
#include "api/limits.hpp"
#include "tests/fuzz/api_limits.hpp"
#include "tests/fuzz/fuzz_support.hpp"
#include "tests/fuzz/reply_checks.hpp"

namespace {

using Json = nlohmann::json;
using bezier::fuzz::check;

using bezier::fuzz::default_limits;
using bezier::fuzz::tight_limits;
constexpr const auto& kPaths = bezier::fuzz::kApiPaths;

/// Builds one request, remembering whether it broke any documented rule.
class RequestBuilder {
 public:
  RequestBuilder(FuzzedDataProvider& data, const bezier::api::Limits& limits)
      : data_(data), numbers_(data), limits_(limits) {}

  /// True while every field is valid by the spec (so the answer must be 200 or work cap).
  [[nodiscard]] bool valid() const noexcept { return valid_; }

  Json evaluate() {
    Json request = {{"points", points(/*allow_3d=*/true, 0)}};
    parameters(request, /*required=*/true);
    if (flip(4)) {
      const int k = data_.ConsumeIntegralInRange<int>(-1, limits_.max_degree + 1);
      valid_ = valid_ && 0 <= k && k <= limits_.max_degree;
      request["derivatives"] = k;
      // The answer's size rule (openapi: t values times (derivatives + 1) at most max_t_values).
      std::size_t values = 1;
      if (const auto t = request.find("t"); t != request.end() && t->is_array()) {
        values = t->size();
      } else if (const auto n = request.find("samples"); n != request.end() && n->is_number_integer()) {
        values = static_cast<std::size_t>(std::max(0, n->get<int>()));
      }
      valid_ = valid_ && values * static_cast<std::size_t>(std::max(k, 0) + 1) <=
                             static_cast<std::size_t>(limits_.max_t_values);
    }
    if (flip(4)) request["split"] = any_number();
    return request;
  }

  Json polar() {
    Json request = {{"points", points(/*allow_3d=*/true, 0)}};
    const int degree = static_cast<int>(request["points"].size()) - 1;
    if (flip(2)) {
      request["t0"] = any_number();
    } else {
      const int k = data_.ConsumeIntegralInRange<int>(0, limits_.max_degree + 1);
      valid_ = valid_ && 1 <= k && k <= degree;
      Json t0 = Json::array();
      for (int i = 0; i < k; ++i) t0.push_back(any_number());
      request["t0"] = std::move(t0);
    }
    if (flip(2)) parameters(request, /*required=*/false);
    return request;
  }

  Json loop_area() {
    Json request = {{"points", points(/*allow_3d=*/false, 0)}};
    if (flip(3)) {
      const double t1 = unit_number(), t2 = unit_number();
      valid_ = valid_ && std::isfinite(t1) && std::isfinite(t2) && 0 <= t1 && t1 < t2 && t2 <= 1;
      request["interval"] = {t1, t2};
    }
    return request;
  }

  Json intersections() {
    Json curves = Json::array();
    const int count = flip(16) ? data_.ConsumeIntegralInRange<int>(0, 3) : 2 - flip(3);
    valid_ = valid_ && (count == 1 || count == 2);
    for (int i = 0; i < count; ++i) curves.push_back({{"points", points(/*allow_3d=*/false, 0)}});
    Json request = {{"curves", std::move(curves)}};
    if (flip(3)) {
      constexpr std::array kTolerances = {1e-12, 1e-9, 1e-6, 1e-3};
      const auto pick = data_.ConsumeIntegralInRange<std::size_t>(0, kTolerances.size());
      if (pick < kTolerances.size()) {
        request["tolerance"] = kTolerances[pick];
      } else {
        valid_ = false;  // any number: its validity is the route's business
        request["tolerance"] = any_number();
      }
    }
    if (flip(3)) {
      constexpr std::array<const char*, 4> kMethods = {"hybrid", "bezier-clipping", "subdivision",
                                                       "newton"};
      const auto pick = data_.ConsumeIntegralInRange<std::size_t>(0, kMethods.size() - 1);
      valid_ = valid_ && pick < 3;
      request["method"] = kMethods[pick];
    }
    if (flip(3)) {
      const int k = data_.ConsumeIntegralInRange<int>(1, 4);
      valid_ = valid_ && (k == 2 || k == 3);
      request["fat_curve_degree"] = k;
    }
    return request;
  }

  Json classify() { return {{"points", points(/*allow_3d=*/false, 4)}}; }

 private:
  /// True with probability 1/n.
  bool flip(int n) { return data_.ConsumeIntegralInRange<int>(0, n - 1) == 0; }

  /// Any double, written as JSON (NaN and infinities become null: invalid).
  Json any_number() {
    const double x = numbers_.any();
    valid_ = valid_ && std::isfinite(x);
    return x;
  }

  /// Mostly a parameter in [0,1] (the unit interval's ends often), sometimes anything.
  double unit_number() {
    switch (data_.ConsumeIntegralInRange<int>(0, 4)) {
      case 0:
        return 0.0;
      case 1:
        return 1.0;
      case 2:
        return numbers_.any();
      default:
        return data_.ConsumeProbability<double>();
    }
  }

  /// `count` points (0: a degree from the fuzzer, mostly within the limit), 2-D or, when
  /// allowed, 3-D; now and then a ragged point or a string instead of a number.
  Json points(bool allow_3d, int count) {
    if (count == 0) {
      count = flip(16) ? data_.ConsumeIntegralInRange<int>(0, limits_.max_degree + 2)
                       : data_.ConsumeIntegralInRange<int>(1, limits_.max_degree) + 1;
    } else if (flip(32)) {
      count += data_.ConsumeBool() ? 1 : -1;
      valid_ = false;  // classify: exactly four
    }
    valid_ = valid_ && 2 <= count && count <= limits_.max_degree + 1;
    const std::size_t dimension = allow_3d && flip(3) ? 3 : 2;
    Json list = Json::array();
    for (int i = 0; i < count; ++i) {
      Json p = Json::array();
      std::size_t d = dimension;
      if (flip(64)) {  // a ragged point
        d = dimension == 2 ? 3 : 2;
        valid_ = false;
      }
      for (std::size_t k = 0; k < d; ++k) p.push_back(flip(128) ? wrong_type() : any_number());
      list.push_back(std::move(p));
    }
    return list;
  }

  Json wrong_type() {
    valid_ = false;
    return "1";
  }

  /// `t` (number or array) or `samples`, or (rarely) both or neither.
  void parameters(Json& request, bool required) {
    switch (data_.ConsumeIntegralInRange<int>(0, 15)) {
      case 0:  // neither
        valid_ = valid_ && !required;
        return;
      case 1:  // both
        request["t"] = any_number();
        request["samples"] = 2;
        valid_ = false;
        return;
      case 2:
      case 3:
      case 4: {
        const int n = flip(32) ? data_.ConsumeIntegralInRange<int>(0, limits_.max_t_values + 1)
                               : data_.ConsumeIntegralInRange<int>(0, 17);
        valid_ = valid_ && 1 <= n && n <= limits_.max_t_values;
        request["samples"] = n;
        return;
      }
      case 5:
      case 6:
      case 7:
      case 8: {
        const int n = data_.ConsumeIntegralInRange<int>(0, 9);
        valid_ = valid_ && 1 <= n && n <= limits_.max_t_values;
        Json ts = Json::array();
        for (int i = 0; i < n; ++i) ts.push_back(flip(2) ? Json(unit_number()) : any_number());
        for (const auto& t : ts) valid_ = valid_ && std::isfinite(t.get<double>());
        request["t"] = std::move(ts);
        return;
      }
      default: {
        const double t = flip(2) ? unit_number() : numbers_.any();
        valid_ = valid_ && std::isfinite(t);
        request["t"] = t;
        return;
      }
    }
  }

  FuzzedDataProvider& data_;
  bezier::fuzz::NumberSource numbers_;
  const bezier::api::Limits& limits_;
  bool valid_ = true;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const std::size_t route = (data[0] & 7u) % kPaths.size();
  const std::string_view path = kPaths[route];
  if (!bezier::api::is_post_route(path)) return -1;
  const bezier::api::Limits limits = (data[0] & 8u) ? tight_limits() : default_limits();
  FuzzedDataProvider provider(data + 1, size - 1);
  RequestBuilder builder(provider, limits);
  Json request;
  switch (route) {
    case 0:
      request = builder.evaluate();
      break;
    case 1:
      request = builder.polar();
      break;
    case 2:
      request = builder.loop_area();
      break;
    case 3:
      request = builder.intersections();
      break;
    default:
      request = builder.classify();
      break;
  }
  const std::string body = request.dump();
  if (bezier::fuzz::print_inputs())
    std::fprintf(stderr, "%.*s %s\n", static_cast<int>(path.size()), path.data(), body.c_str());
  const bezier::api::Reply reply = bezier::api::handle(path, body, limits);
  bezier::fuzz::check_reply(body, reply);
  check(reply.status != 400, [&] { return "400 for a JSON object: " + reply.body; });
  if (builder.valid()) {
    // Besides 200: the work cap, and (since finding F1) a result beyond the double range.
    const bool work_cap = reply.status == 422 && reply.body.find("work-cap") != std::string::npos;
    const bool overflow =
        reply.status == 422 && reply.body.find("double range") != std::string::npos;
    check(reply.status == 200 || work_cap || overflow, [&] {
      return "a request within the documented rules was rejected: " + body + "\n  -> " +
             reply.body.substr(0, 2000);
    });
  }
  return 0;
}
