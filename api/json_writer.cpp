#include "api/json_writer.hpp"

#include <cassert>
#include <string_view>
#include <vector>

namespace bezier::api {

std::string JsonWriter::first_non_finite_pointer() const {
  assert(!all_finite());
  // The text up to the number (its separating comma included) is well-formed JSON with
  // its containers still open: each open bracket is a level of the path, an array's
  // commas count its index, and an object's last key before the number names its member.
  struct Level {
    bool object;
    std::size_t index;
    std::string_view key;
  };
  std::vector<Level> path;
  const std::string_view text(out_.data(), first_non_finite_);
  for (std::size_t i = 0; i < text.size(); ++i) {
    switch (text[i]) {
      case '"': {
        std::size_t end = i + 1;
        while (text[end] != '"') end += text[end] == '\\' ? 2 : 1;
        if (end + 1 < text.size() && text[end + 1] == ':') path.back().key = text.substr(i + 1, end - i - 1);
        i = end;
        break;
      }
      case '{':
        path.push_back({true, 0, {}});
        break;
      case '[':
        path.push_back({false, 0, {}});
        break;
      case '}':
      case ']':
        path.pop_back();
        break;
      case ',':
        if (!path.back().object) ++path.back().index;
        break;
      default:
        break;
    }
  }
  std::string pointer;
  for (const Level& level : path) {
    pointer += '/';
    pointer += level.object ? std::string(level.key) : std::to_string(level.index);
  }
  return pointer;
}

}  // namespace bezier::api
