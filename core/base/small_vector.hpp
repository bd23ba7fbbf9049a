#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace bezier::core {

/// A sequence of trivially copyable values (the control points of a curve) stored inline up
/// to N entries and in a std::vector beyond: a value type, copies are deep.
///
/// Why not std::vector: every curve the kernel builds (a piece from portion, an edge of an
/// arrangement, a reversed copy, a hodograph, a copy into a path) holds its control points
/// here, and with a std::vector each of them is a heap allocation and a free, a large share
/// of the boolean operations' time. Curves of degree below N need none.
///
/// The inline entries are all value-initialised, so that a copy copies the whole fixed-size
/// array (no branch on the size) without reading an unset value.
/// Invariant: size() > N exactly when the entries are in `heap_` (heap_.size() == size());
/// otherwise heap_ holds nothing. A moved-from sequence is empty.
template <class T, std::size_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable_v<T> && std::is_nothrow_default_constructible_v<T>,
                "the inline entries are plain values, copied and moved without throwing");
  static_assert(N > 0);

 public:
  static constexpr std::size_t kInline = N;

  SmallVector() noexcept = default;
  /// n value-initialised entries.
  explicit SmallVector(std::size_t n) { resize(n); }
  explicit SmallVector(std::span<const T> values) { assign(values); }
  SmallVector(std::initializer_list<T> values) {
    assign(std::span<const T>(values.begin(), values.size()));
  }
  /// The values of `values`, whose storage is kept when they do not fit inline.
  explicit SmallVector(std::vector<T>&& values) noexcept : size_(values.size()) {
    if (size_ > N) {
      heap_ = std::move(values);
    } else {
      std::copy(values.begin(), values.end(), inline_entries());
    }
  }

  SmallVector(const SmallVector& other) : inline_(other.inline_), size_(other.size_) {
    if (size_ > N) heap_ = other.heap_;
  }
  SmallVector& operator=(const SmallVector& other) {
    if (this == &other) return *this;
    if (other.size_ > N) {
      heap_ = other.heap_;
    } else {
      heap_.clear();
      inline_ = other.inline_;
    }
    size_ = other.size_;
    return *this;
  }
  SmallVector(SmallVector&& other) noexcept
      : inline_(other.inline_), heap_(std::move(other.heap_)), size_(other.size_) {
    other.heap_.clear();
    other.size_ = 0;
  }
  SmallVector& operator=(SmallVector&& other) noexcept {
    if (this == &other) return *this;
    if (other.size_ > N) {
      heap_ = std::move(other.heap_);
    } else {
      heap_.clear();
      inline_ = other.inline_;
    }
    size_ = other.size_;
    other.heap_.clear();
    other.size_ = 0;
    return *this;
  }
  ~SmallVector() = default;

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] T* data() noexcept { return size_ > N ? heap_.data() : inline_entries(); }
  [[nodiscard]] const T* data() const noexcept { return size_ > N ? heap_.data() : inline_entries(); }
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
  [[nodiscard]] T& front() noexcept { return (*this)[0]; }
  [[nodiscard]] const T& front() const noexcept { return (*this)[0]; }
  [[nodiscard]] T& back() noexcept { return (*this)[size_ - 1]; }
  [[nodiscard]] const T& back() const noexcept { return (*this)[size_ - 1]; }
  [[nodiscard]] std::span<const T> span() const noexcept { return {data(), size_}; }
  [[nodiscard]] std::span<T> span() noexcept { return {data(), size_}; }

  /// Room for n entries without a further allocation.
  void reserve(std::size_t n) {
    if (n > N) heap_.reserve(n);
  }

  /// Size n; entries beyond the old size are value-initialised.
  void resize(std::size_t n) {
    if (n > N) {
      if (size_ <= N) heap_.assign(inline_entries(), inline_entries() + size_);
      heap_.resize(n);
    } else {
      if (size_ > N) std::copy(heap_.begin(), heap_.begin() + static_cast<std::ptrdiff_t>(n), inline_entries());
      heap_.clear();
      std::fill(inline_entries() + std::min(size_, n), inline_entries() + n, T{});
    }
    size_ = n;
  }

  void push_back(const T& value) {
    if (size_ < N) {
      inline_entries()[size_] = value;
    } else {
      if (size_ == N) heap_.assign(inline_entries(), inline_entries() + N);
      heap_.push_back(value);
    }
    ++size_;
  }

  /// The entries as a std::vector, taken out of a sequence that is not used again (no copy
  /// when they are on the heap).
  [[nodiscard]] std::vector<T> take_vector() && {
    std::vector<T> out = size_ > N ? std::move(heap_) : std::vector<T>(begin(), end());
    heap_.clear();
    size_ = 0;
    return out;
  }

  friend bool operator==(const SmallVector& a, const SmallVector& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  void assign(std::span<const T> values) {
    if (values.size() > N) {
      heap_.assign(values.begin(), values.end());
    } else {
      heap_.clear();
      std::copy(values.begin(), values.end(), inline_entries());
    }
    size_ = values.size();
  }

  [[nodiscard]] T* inline_entries() noexcept { return inline_.data(); }
  [[nodiscard]] const T* inline_entries() const noexcept { return inline_.data(); }

  std::array<T, N> inline_{};  // value-initialised, so that copies of unused entries are defined
  std::vector<T> heap_;
  std::size_t size_ = 0;
};

}  // namespace bezier::core
