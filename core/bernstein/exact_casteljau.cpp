#include "core/bernstein/exact_casteljau.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/numeric/outward.hpp"

namespace bezier::core {

namespace {

constexpr int kLowestBit = -1074;

// The exponent of x's least significant set bit (x finite, nonzero).
int lowest_bit(double x) {
  int exponent = 0;
  const double mantissa = std::frexp(std::fabs(x), &exponent);  // in [1/2, 1)
  const auto integer = static_cast<std::uint64_t>(std::ldexp(mantissa, 53));
  return exponent - 53 + std::countr_zero(integer);
}

// Whether `rounds` rounds at parameters whose lowest bits are at least `parameter_bit` keep
// the coefficients c exact (the header's condition).
bool rounds_stay_exact(std::span<const double> c, int rounds, int parameter_bit) {
  int coefficient_bit = std::numeric_limits<int>::max();
  for (const double x : c) {
    if (!std::isfinite(x) || std::fabs(x) > 0x1p1000) return false;
    if (x != 0.0) coefficient_bit = std::min(coefficient_bit, lowest_bit(x));
  }
  if (coefficient_bit == std::numeric_limits<int>::max()) return true;  // all zero
  return coefficient_bit + static_cast<long>(rounds) * parameter_bit >= kLowestBit;
}

// The parameter's lowest bit for the check; 0 (no product changes a bit) for t = 0.
int parameter_bit(double t) { return t == 0.0 ? 0 : std::min(0, lowest_bit(t)); }

// One round at t over row[0..count): row[i] = row[i] + t (row[i + 1] - row[i]).
void round_at(std::vector<Expansion>& row, std::size_t count, double t) {
  for (std::size_t i = 0; i + 1 < count; ++i) row[i] = row[i] + (row[i + 1] - row[i]) * t;
}

}  // namespace

std::optional<Expansion> exact_value(std::span<const double> c, double t) {
  const std::size_t n = c.size() - 1;
  if (!rounds_stay_exact(c, static_cast<int>(n), parameter_bit(t))) return std::nullopt;
  std::vector<Expansion> row(c.begin(), c.end());
  for (std::size_t count = c.size(); count > 1; --count) round_at(row, count, t);
  return row[0];
}

std::optional<std::vector<Expansion>> exact_portion(std::span<const double> c, double a, double b) {
  const std::size_t n = c.size() - 1;
  if (!rounds_stay_exact(c, static_cast<int>(n), std::min(parameter_bit(a), parameter_bit(b)))) {
    return std::nullopt;
  }
  // rows_a after k rounds at a holds n + 1 - k entries; coefficient i finishes the row of
  // n - i rounds at a (i + 1 entries) with i rounds at b.
  std::vector<Expansion> row(c.begin(), c.end());
  std::vector<Expansion> out(n + 1);
  for (std::size_t rounds_a = 0; rounds_a <= n; ++rounds_a) {
    const std::size_t i = n - rounds_a;
    std::vector<Expansion> rest(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(i + 1));
    for (std::size_t count = i + 1; count > 1; --count) round_at(rest, count, b);
    out[i] = rest[0];
    round_at(row, n + 1 - rounds_a, a);
  }
  return out;
}

double rounded_down(const Expansion& e) {
  double x = e.estimate();
  while ((e - Expansion(x)).sign() < 0) x = next_down(x);
  return x;
}

double rounded_up(const Expansion& e) {
  double x = e.estimate();
  while ((e - Expansion(x)).sign() > 0) x = next_up(x);
  return x;
}

}  // namespace bezier::core
