#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "api/problem.hpp"
#include "core/base/curve.hpp"

namespace bezier::api {

using Json = nlohmann::json;

/// The JSON Pointer of `key` inside the object at `parent` (RFC 6901 escaping).
[[nodiscard]] std::string pointer_to(const std::string& parent, std::string_view key);
/// The JSON Pointer of element `index` inside the array at `parent`.
[[nodiscard]] std::string pointer_to(const std::string& parent, std::size_t index);

/// Reads typed values out of a request, recording every problem with the JSON Pointer
/// of the offending field instead of stopping at the first, so a client sees all its
/// mistakes at once. Each reader returns nullopt when the value is rejected.
class RequestReader {
 public:
  explicit RequestReader(const Limits& limits) : limits_(limits) {}

  [[nodiscard]] const Limits& limits() const noexcept { return limits_; }
  void fail(std::string pointer, std::string message);
  /// fail() for a value refused by one of limits() (above it, or a message that names it):
  /// the refusal then says so (Reply::limit_reached), even when the error list is full.
  void fail_limit(std::string pointer, std::string message);
  [[nodiscard]] bool ok() const noexcept { return errors_.empty(); }
  /// The 422 of every recorded error (precondition: !ok()), limit_reached when one of
  /// them was a limit's.
  [[nodiscard]] Reply refusal();

  /// Rejects every member of `object` whose name is not in `known` (typos must not be
  /// silently ignored: a misspelt `derivative` would otherwise return no derivatives).
  void reject_unknown_fields(const Json& object, std::initializer_list<std::string_view> known,
                             const std::string& pointer);

  /// The member `key` of `object`; records "required" when absent.
  const Json* required(const Json& object, std::string_view key, const std::string& pointer);
  /// The member `key` of `object`, or nullptr when absent (null counts as absent).
  [[nodiscard]] static const Json* optional(const Json& object, std::string_view key);

  /// A finite JSON number.
  std::optional<double> number(const Json& value, const std::string& pointer);
  /// A finite number in [lo, hi].
  std::optional<double> number_in(const Json& value, const std::string& pointer, double lo,
                                  double hi);
  /// What the upper bound of a range is: a fixed rule of the API, or a value of limits()
  /// (then a value out of the range is refused through fail_limit: the message names the
  /// limit, even for a value below lo).
  enum class Bound { fixed, limit };
  /// An integer in [lo, hi] (1.0 is accepted as an integer, 1.5 is not).
  std::optional<int> integer(const Json& value, const std::string& pointer, int lo, int hi,
                             Bound hi_is = Bound::fixed);
  /// A non-empty array of at most limits().max_t_values finite numbers, each in [lo, hi]
  /// (more values is a limit's refusal).
  std::optional<std::vector<double>> numbers(const Json& value, const std::string& pointer,
                                             double lo, double hi);
  /// A number or an array of numbers, each in [lo, hi].
  std::optional<std::vector<double>> number_or_numbers(const Json& value,
                                                       const std::string& pointer, double lo,
                                                       double hi);
  /// One of the strings in `allowed`.
  std::optional<std::string> one_of(const Json& value, const std::string& pointer,
                                    std::initializer_list<std::string_view> allowed);

  /// Where to evaluate, read from the request object: `t` (a number or an array, any
  /// finite values) or `samples` (a count N: t_i = i / (N - 1), 0 and 1 included), not
  /// both. When neither is given: empty, or an error at /t if `required`.
  std::vector<double> parameters(const Json& request, bool required);

  /// Control points of a planar curve: 2 to max_degree + 1 points [x, y] (more is a limit's
  /// refusal).
  std::optional<core::Curve> curve2(const Json& value, const std::string& pointer);
  /// Control points of a planar or space curve: every point [x, y] or every point [x, y, z].
  std::optional<std::variant<core::Curve, core::Curve3>> curve(const Json& value,
                                                               const std::string& pointer);
  /// The required member `points` of the request object: curve() at /points.
  std::optional<std::variant<core::Curve, core::Curve3>> request_curve(const Json& request);

 private:
  /// Shared by curve2 and curve: dimension 0 means "2 or 3, all alike".
  std::optional<std::variant<core::Curve, core::Curve3>> read_curve(const Json& value,
                                                                    const std::string& pointer,
                                                                    std::size_t dimension);

  const Limits& limits_;
  std::vector<FieldError> errors_;
  bool limit_reached_ = false;
};

}  // namespace bezier::api
