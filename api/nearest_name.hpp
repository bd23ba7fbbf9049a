#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace bezier::api {

/// The Levenshtein distance between a and b (insertions, deletions and substitutions of
/// one byte each), in O(|a| |b|) time; ASCII letters compare case-insensitively.
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate nearest to `name` by edit_distance (the first of equals) when it is close
/// enough to be a likely misspelling: at most 2 edits, at most a third of the longer
/// name's length (rounded up), and fewer than its length (so that one-letter names do not
/// match every other one-letter name); nullopt
/// otherwise. `name` beyond 64 bytes matches nothing (the distance table stays small).
[[nodiscard]] std::optional<std::string_view> nearest_name(std::string_view name,
                                                          std::span<const std::string_view> candidates);

/// " (did you mean `x`?)" for nearest_name's x, "" when there is none.
[[nodiscard]] std::string did_you_mean(std::string_view name, std::span<const std::string_view> candidates);

}  // namespace bezier::api
