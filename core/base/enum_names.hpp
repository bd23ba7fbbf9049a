#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace bezier::core {

/// The names of an enumeration's values, as the API writes them, listed in the order of its
/// enumerators (numbered 0, 1, 2, ... as by default); `Last` is the last enumerator, so a
/// list with a name too few or too many does not compile. A lookup instead of a switch per
/// enumeration.
template <auto Last>
class EnumNames {
 public:
  using Enum = decltype(Last);
  static constexpr std::size_t kCount = static_cast<std::size_t>(Last) + 1;

  template <class... Names>
    requires(sizeof...(Names) == kCount)
  consteval explicit EnumNames(Names... names) : names_{std::string_view(names)...} {}

  [[nodiscard]] constexpr std::string_view operator()(Enum value) const noexcept {
    return names_[static_cast<std::size_t>(value)];
  }

 private:
  std::array<std::string_view, kCount> names_;
};

}  // namespace bezier::core
