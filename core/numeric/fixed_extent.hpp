#pragma once

#include <cstddef>
#include <span>
#include <type_traits>

namespace bezier::core {

/// The number of coefficients E of a low-degree piece as a compile-time constant, for the
/// hot loops of the search: `with_fixed_extent(size, fn)` calls
/// fn(std::integral_constant<std::size_t, E>{}) with E = size for the sizes 2, 3 and 4
/// (degrees 1 to 3, every piece of the cubic benchmark), and with E = std::dynamic_extent
/// for any other size. A function body written once over std::span<const double, E> then
/// runs with its loops unrolled and its branches on the degree folded for lines,
/// quadratics and cubics, and unchanged for the rest: the same operations in the same
/// order, so the same results bit for bit, at every degree.
template <class Fn>
decltype(auto) with_fixed_extent(std::size_t size, Fn&& fn) {
  switch (size) {
    case 2:
      return fn(std::integral_constant<std::size_t, 2>{});
    case 3:
      return fn(std::integral_constant<std::size_t, 3>{});
    case 4:
      return fn(std::integral_constant<std::size_t, 4>{});
    default:
      return fn(std::integral_constant<std::size_t, std::dynamic_extent>{});
  }
}

/// The `size` values at `data` as a span of extent E (E = size unless E is dynamic).
template <std::size_t E>
[[nodiscard]] std::span<const double, E> fixed_span(const double* data, std::size_t size) noexcept {
  return std::span<const double, E>(data, size);
}

}  // namespace bezier::core
