#pragma once

#include <optional>
#include <string_view>

namespace bezier::service {

/// A file of the playground page, compiled into the binary (nothing is read from disk
/// or downloaded at run time).
struct StaticFile {
  std::string_view content;
  std::string_view content_type;
};

/// The playground file served at `path`: "/" is service/playground/index.html, and
/// "/playground/<name>" is service/playground/<name>. nullopt for anything else.
[[nodiscard]] std::optional<StaticFile> find_static_file(std::string_view path) noexcept;

}  // namespace bezier::service
