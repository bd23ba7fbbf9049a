// libFuzzer target: the work cap bounds CPU time. Each input is one request to a route
// whose kernel is iterative (/intersections with two curves or one, /loop-area) with a
// work budget (Limits::max_work) picked from the input; the request's CPU time
// (CLOCK_THREAD_CPUTIME_ID around api::handle) must stay below a fixed multiple of what
// the budget buys, whatever the coordinates, the degrees and the method.
//
// Input (FuzzedDataProvider; tests/fuzz/make_seeds.py writes the seeds): the budget
// (22 000 000 units, the API default, or a tenth, a hundredth, a thousandth of it), the
// request (two curves, one curve, loop area), the method (hybrid with fat curves of degree 3
// or 2, Bézier clipping, subdivision), then each curve: its degree (1-4 mostly, up to 20)
// and its coordinates. A coordinate is zero, a small integer, m 10^e with e anywhere in
// -300 ... 300 (hostile magnitudes: 1e-300 beside 1e300 in one curve), the previous one a
// few ulps away, a dyadic fraction, or raw IEEE bits (finite ones).
//
// What a unit costs is measured once, at start-up, on a request that spends its whole
// budget in plain search steps (seconds_per_unit in unit_cpu_time.hpp). An input fails when
//   cpu > kMultiple * unit * (budget + kFixedUnits),
// kFixedUnits standing for what every request costs whatever its budget: the JSON, the
// phases bounded by the degrees (factorisations of improper curves, up to about a
// millisecond at degree 20), and the page faults of a first execution. The multiple leaves room for the cost
// model's spread between paths (docs/WORK_CAPS.md) and for a noisy machine; a path whose
// time the work units do not bound exceeds it by orders of magnitude.
// Also checked: the answer is 200 or 422 (never a 500).
//
// Build it without sanitizers (docs/FUZZING.md): ASan slows allocation-heavy code much
// more than arithmetic, which would skew the ratio it checks.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "api/handler.hpp"
#include "api/limits.hpp"
#include "tests/fuzz/fuzz_support.hpp"
#include "tests/fuzz/unit_cpu_time.hpp"

namespace {

using Json = nlohmann::json;
using bezier::fuzz::check;

constexpr double kMultiple = 3.0;
constexpr double kFixedUnits = 500000.0;
constexpr std::array<std::int64_t, 4> kBudgets = {22000000, 2200000, 220000, 22000};

struct Timed {
  bezier::api::Reply reply;
  double cpu = 0.0;
};

Timed timed_handle(const std::string& path, const std::string& body, std::int64_t budget) {
  bezier::api::Limits limits;
  limits.max_work = budget;
  const double start = bezier::fuzz::thread_cpu_seconds();
  bezier::api::Reply reply = bezier::api::handle(path, body, limits);
  const double cpu = bezier::fuzz::thread_cpu_seconds() - start;
  return {std::move(reply), cpu};
}

/// Coordinates of every magnitude a request can carry.
class HostileNumbers {
 public:
  explicit HostileNumbers(FuzzedDataProvider& data) : data_(data) {}

  double next() {
    previous_ = make();
    return previous_;
  }

 private:
  double make() {
    switch (data_.ConsumeIntegral<std::uint8_t>() % 6) {
      case 0:
        return 0.0;
      case 1:
        return data_.ConsumeIntegralInRange<int>(-8, 8);
      case 2: {
        // m 10^e, by the C library's decimal conversion (correctly rounded).
        const int m = data_.ConsumeIntegral<std::int16_t>();
        const int e = data_.ConsumeIntegralInRange<int>(-300, 300);
        char text[32];
        std::snprintf(text, sizeof text, "%de%d", m, e);
        return std::strtod(text, nullptr);
      }
      case 3: {
        double x = previous_;
        const int ulps = data_.ConsumeIntegralInRange<int>(-2, 2);
        for (int i = 0; i < std::abs(ulps); ++i)
          x = std::nextafter(x, ulps > 0 ? INFINITY : -INFINITY);
        return std::isfinite(x) ? x : previous_;
      }
      case 4: {
        const int k = data_.ConsumeIntegral<std::int16_t>();
        const int j = data_.ConsumeIntegralInRange<int>(0, 20);
        return std::ldexp(k, -j);
      }
      default: {
        const double x = std::bit_cast<double>(data_.ConsumeIntegral<std::uint64_t>());
        return std::isfinite(x) ? x : 0.0;
      }
    }
  }

  FuzzedDataProvider& data_;
  double previous_ = 0.0;
};

Json curve(FuzzedDataProvider& data, HostileNumbers& numbers) {
  const auto b = data.ConsumeIntegral<std::uint8_t>();
  const int degree = b < 192 ? 1 + b % 4 : 1 + b % 20;
  Json points = Json::array();
  for (int i = 0; i <= degree; ++i) {
    const double x = numbers.next();
    const double y = numbers.next();
    points.push_back({x, y});
  }
  return {{"points", std::move(points)}};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const double unit = bezier::fuzz::seconds_per_unit("work_bound_fuzzer");
  FuzzedDataProvider data(bytes, size);
  const std::int64_t budget = kBudgets[data.ConsumeIntegralInRange<std::size_t>(0, 3)];
  const int route = data.ConsumeIntegralInRange<int>(0, 2);
  const int method = data.ConsumeIntegralInRange<int>(0, 3);
  HostileNumbers numbers(data);
  Json request;
  std::string path = "/intersections";
  if (route == 2) {
    path = "/loop-area";
    request = curve(data, numbers);
  } else {
    Json curves = Json::array({curve(data, numbers)});
    if (route == 0) curves.push_back(curve(data, numbers));
    request = {{"curves", std::move(curves)}};
    constexpr std::array<const char*, 4> kMethods = {"hybrid", "hybrid", "bezier-clipping",
                                                     "subdivision"};
    request["method"] = kMethods[static_cast<std::size_t>(method)];
    if (method == 1) request["fat_curve_degree"] = 2;
  }
  const std::string body = request.dump();
  if (bezier::fuzz::print_inputs()) {
    std::fprintf(stderr, "%s budget %lld: %s\n", path.c_str(), static_cast<long long>(budget),
                 body.c_str());
  }
  const Timed t = timed_handle(path, body, budget);
  check(t.reply.status == 200 || t.reply.status == 422, [&] {
    return "status " + std::to_string(t.reply.status) + " for " + path + " " + body;
  });
  const double limit = kMultiple * unit * (static_cast<double>(budget) + kFixedUnits);
  check(t.cpu <= limit, [&] {
    char figures[160];
    std::snprintf(figures, sizeof figures, "%.4f s of CPU, over the %.4f s that %lld units allow: ",
                  t.cpu, limit, static_cast<long long>(budget));
    return std::string(figures) + path + " " + body;
  });
  return 0;
}
