#pragma once

// A request whose cost is its work cap, for the tests of the compute queue: the
// intersections of (t, T_20(2t - 1)) and its mirror image (T_20(2s - 1), s), 400 crossings,
// by plain subdivision, which needs more work than any cap the tests set and so answers
// 422 work-cap after spending the whole budget (--max-work): CPU time in proportion to
// the cap, whatever the machine.
#include <cstdint>
#include <cstdio>
#include <string>

namespace bezier::test {

inline double binomial(int n, int k) {
  std::uint64_t c = 1;  // exact: C(40, 20) < 2^38
  for (int i = 1; i <= k; ++i) c = c * static_cast<std::uint64_t>(n - k + i) / static_cast<std::uint64_t>(i);
  return static_cast<double>(c);
}

/// The body of POST /intersections described above.
inline std::string work_cap_bound_intersections() {
  constexpr int n = 20;
  std::string wave = "[";
  std::string mirrored = "[";
  for (int k = 0; k <= n; ++k) {
    // Bernstein coefficients of T_n(2t - 1): (-1)^(n-k) C(2n, 2k) / C(n, k).
    const double c = ((n - k) % 2 == 0 ? 1.0 : -1.0) * binomial(2 * n, 2 * k) / binomial(n, k);
    const double t = static_cast<double>(k) / n;
    char point[96];
    std::snprintf(point, sizeof point, "%s[%.17g,%.17g]", k == 0 ? "" : ",", t, c);
    wave += point;
    std::snprintf(point, sizeof point, "%s[%.17g,%.17g]", k == 0 ? "" : ",", c, t);
    mirrored += point;
  }
  return R"({"curves":[{"points":)" + wave + R"(]},{"points":)" + mirrored + R"(]}],"method":"subdivision"})";
}

/// SVG path data of a unit circle of four cubics traced 1000 times: every segment meets its
/// 999 copies, so a path's self-intersection sweep finds millions of candidate pairs
/// (what the memory limit and the memory returned after a burst are tested with).
inline std::string circle_traced_1000_times_path() {
  const std::string k = "0.5522847498";
  const std::string turn = "C1 " + k + " " + k + " 1 0 1 C-" + k + " 1 -1 " + k + " -1 0 C-1 -" + k + " -" + k +
                           " -1 0 -1 C" + k + " -1 1 -" + k + " 1 0 ";
  std::string path = "M1 0 ";
  for (int i = 0; i < 1000; ++i) path += turn;
  return path;
}

}  // namespace bezier::test
