#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/numeric/tuning.hpp"

namespace bezier::core {

/// A short sequence of values (Bernstein coefficients of one coordinate of a piece), stored
/// inline up to kInline entries (numeric_tuning::kInlineEntries) and on the heap beyond, so
/// the clipping loop allocates nothing for the degrees the API accepts by default. A value
/// type: copies are deep.
///
/// The inline entries are bytes in which the entries exist without being initialised (T is
/// trivially copyable and destructible, so creating the byte array creates them), so a
/// short array, or one asked for Uninitialized entries, writes none of the kInline entries
/// beyond what it is given, even where T's members have default initialisers.
template <class T>
class SmallArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "the inline entries are created by their storage, without construction");

 public:
  static constexpr std::size_t kInline = numeric_tuning::kInlineEntries;

  SmallArray() noexcept {}  // NOLINT(modernize-use-equals-default): leaves the entries unset
  SmallArray(const SmallArray& other) { *this = other; }
  SmallArray& operator=(const SmallArray& other) {
    if (this == &other) return *this;
    if (other.size_ > kInline)
      heap_ = other.heap_;
    else
      std::copy(other.inline_entries(), other.inline_entries() + other.size_, inline_entries());
    size_ = other.size_;
    return *this;
  }
  SmallArray(SmallArray&& other) noexcept { *this = std::move(other); }
  SmallArray& operator=(SmallArray&& other) noexcept {
    if (this == &other) return *this;
    if (other.size_ > kInline)
      heap_ = std::move(other.heap_);
    else
      std::copy(other.inline_entries(), other.inline_entries() + other.size_, inline_entries());
    size_ = other.size_;
    other.heap_.clear();
    other.size_ = 0;  // a moved-from array is empty, whichever storage it had
    return *this;
  }
  ~SmallArray() = default;
  explicit SmallArray(std::size_t n, T value = T{}) { resize(n, value); }
  /// n entries left unset, for buffers that are written before they are read.
  struct Uninitialized {};
  SmallArray(std::size_t n, Uninitialized) { resize(n, Uninitialized{}); }
  explicit SmallArray(std::span<const T> values) {
    resize(values.size());
    std::copy(values.begin(), values.end(), data());
  }

  /// Size n with the entries left unset (heap entries beyond kInline value-initialised).
  void resize(std::size_t n, Uninitialized) {
    if (n > kInline) heap_.resize(n);
    size_ = n;
  }

  void resize(std::size_t n, T value = T{}) {
    if (n > kInline)
      heap_.assign(n, value);
    else
      std::fill(inline_entries(), inline_entries() + n, value);
    size_ = n;
  }

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] T* data() noexcept { return size_ > kInline ? heap_.data() : inline_entries(); }
  [[nodiscard]] const T* data() const noexcept { return size_ > kInline ? heap_.data() : inline_entries(); }
  [[nodiscard]] T& operator[](std::size_t i) noexcept {
    assert(i < size_);
    return data()[i];
  }
  [[nodiscard]] const T& operator[](std::size_t i) const noexcept {
    assert(i < size_);
    return data()[i];
  }
  [[nodiscard]] T* begin() noexcept { return data(); }
  [[nodiscard]] T* end() noexcept { return data() + size_; }
  [[nodiscard]] const T* begin() const noexcept { return data(); }
  [[nodiscard]] const T* end() const noexcept { return data() + size_; }
  [[nodiscard]] T& back() noexcept { return data()[size_ - 1]; }
  [[nodiscard]] const T& back() const noexcept { return data()[size_ - 1]; }
  [[nodiscard]] operator std::span<const T>() const noexcept { return {data(), size_}; }  // NOLINT
  [[nodiscard]] std::span<T> span() noexcept { return {data(), size_}; }

 private:
  [[nodiscard]] T* inline_entries() noexcept { return std::launder(reinterpret_cast<T*>(inline_)); }
  [[nodiscard]] const T* inline_entries() const noexcept {
    return std::launder(reinterpret_cast<const T*>(inline_));
  }

  alignas(T) std::byte inline_[kInline * sizeof(T)];  // the entries, unset until written
  std::vector<T> heap_;
  std::size_t size_ = 0;
};

/// Bernstein coefficients of a scalar polynomial.
using Coeffs = SmallArray<double>;

}  // namespace bezier::core
