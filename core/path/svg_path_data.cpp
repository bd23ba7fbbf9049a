#include "core/path/svg_path_data.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include "core/base/point.hpp"
#include "core/path/elliptical_arc.hpp"

namespace bezier::path {

namespace {

using core::Point2;

/// How much of a refused number a message quotes (then "…"): enough to recognise it.
constexpr std::size_t kQuotedDigits = 64;

/// wsp of the SVG grammar: tab, line feed, form feed, carriage return, space.
bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\f' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
/// A character that can begin a number: it ends the previous argument without a separator.
bool starts_number(char c) { return is_digit(c) || c == '.' || c == '+' || c == '-'; }

/// How many numbers one repetition of a command's arguments has.
int argument_count(char command) {
  switch (command) {
    case 'M': case 'm': case 'L': case 'l': case 'T': case 't': return 2;
    case 'H': case 'h': case 'V': case 'v': return 1;
    case 'S': case 's': case 'Q': case 'q': return 4;
    case 'C': case 'c': return 6;
    case 'A': case 'a': return 7;
    default: return 0;  // Z, z
  }
}

bool is_command(char c) {
  switch (c) {
    case 'M': case 'm': case 'L': case 'l': case 'H': case 'h': case 'V': case 'v':
    case 'C': case 'c': case 'S': case 's': case 'Q': case 'q': case 'T': case 't':
    case 'A': case 'a': case 'Z': case 'z':
      return true;
    default:
      return false;
  }
}

/// The character at an error's offset, as a message shows it.
std::string describe(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x21 && byte < 0x7F) return std::string("'") + c + "'";
  std::array<char, 16> text{};
  std::snprintf(text.data(), text.size(), "byte 0x%02X", byte);
  return text.data();
}

/// Which kind of segment the previous command drew: S and T reflect a control point of the
/// previous segment only when it was drawn by a command of their own family.
enum class Previous { other, cubic, quadratic };

class PathDataParser {
 public:
  PathDataParser(std::string_view data, std::size_t max_segments,
                 std::optional<double> arc_tolerance)
      : data_(data), max_segments_(max_segments), arc_tolerance_(arc_tolerance) {}

  PathDataParse run() {
    skip_wsp();
    if (at_end()) return {};
    if (data_[pos_] != 'M' && data_[pos_] != 'm') {
      return failure(PathDataErrorKind::syntax, pos_,
                     "expected a moveto command (M or m) to begin the path data, found " +
                         describe(data_[pos_]));
    }
    while (!at_end()) {
      const std::size_t command_offset = pos_;
      const char command = data_[pos_];
      if (!is_command(command)) {
        return failure(PathDataErrorKind::syntax, command_offset,
                       "expected a command letter (M, L, H, V, C, S, Q, T, A, Z or their "
                       "lowercase forms), found " + describe(command));
      }
      ++pos_;
      skip_wsp();
      if (command == 'Z' || command == 'z') {
        if (!close_subpath(command_offset)) return take_error();
        continue;
      }
      bool first_group = true;
      while (true) {
        const std::size_t group_offset = first_group ? command_offset : pos_;
        if (!arguments(command, first_group, group_offset)) return take_error();
        first_group = false;
        // Another repetition follows when, after whitespace and at most one comma, a number
        // begins; a comma must be followed by a number.
        skip_wsp();
        if (!at_end() && data_[pos_] == ',') {
          ++pos_;
          skip_wsp();
          if (at_end() || !starts_number(data_[pos_])) {
            return failure(PathDataErrorKind::syntax, pos_, "expected a number after ','");
          }
        }
        if (at_end() || !starts_number(data_[pos_])) break;
      }
    }
    end_subpath();
    return {std::move(path_), std::move(closing_lines_), std::nullopt};
  }

 private:
  [[nodiscard]] bool at_end() const { return pos_ >= data_.size(); }
  void skip_wsp() {
    while (!at_end() && is_wsp(data_[pos_])) ++pos_;
  }

  PathDataParse failure(PathDataErrorKind kind, std::size_t offset, std::string message) {
    error_ = PathDataError{kind, offset, std::move(message)};
    return take_error();
  }
  PathDataParse take_error() { return {Path{}, {}, std::move(error_)}; }
  bool fail(PathDataErrorKind kind, std::size_t offset, std::string message) {
    error_ = PathDataError{kind, offset, std::move(message)};
    return false;
  }

  /// One number at pos_: sign? (digits ('.' digits?)? | '.' digits) ([eE] sign? digits)?.
  bool number(double& value) {
    const std::size_t begin = pos_;
    if (at_end() || !starts_number(data_[pos_])) {
      return fail(PathDataErrorKind::syntax, pos_,
                  at_end() ? std::string("expected a number, found the end of the data")
                           : "expected a number, found " + describe(data_[pos_]));
    }
    if (data_[pos_] == '+' || data_[pos_] == '-') ++pos_;
    std::size_t digits = 0;
    while (!at_end() && is_digit(data_[pos_])) ++pos_, ++digits;
    if (!at_end() && data_[pos_] == '.') {
      ++pos_;
      while (!at_end() && is_digit(data_[pos_])) ++pos_, ++digits;
    }
    if (digits == 0) {
      return fail(PathDataErrorKind::syntax, pos_,
                  at_end() ? std::string("expected a digit, found the end of the data")
                           : "expected a digit, found " + describe(data_[pos_]));
    }
    if (!at_end() && (data_[pos_] == 'e' || data_[pos_] == 'E')) {
      ++pos_;
      if (!at_end() && (data_[pos_] == '+' || data_[pos_] == '-')) ++pos_;
      if (at_end() || !is_digit(data_[pos_])) {
        return fail(PathDataErrorKind::syntax, pos_,
                    at_end() ? std::string("expected a digit of the exponent, found the end of "
                                           "the data")
                             : "expected a digit of the exponent, found " + describe(data_[pos_]));
      }
      while (!at_end() && is_digit(data_[pos_])) ++pos_;
    }
    // from_chars takes no '+'; the token is already known to be a valid number.
    const char* first = data_.data() + begin + (data_[begin] == '+' ? 1 : 0);
    const char* last = data_.data() + pos_;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::result_out_of_range) {
      // Out of range either way: a magnitude beyond the largest double is refused, one below
      // the smallest rounds to a subnormal or zero as any decimal reader rounds it.
      value = std::strtod(std::string(first, last).c_str(), nullptr);
      if (!std::isfinite(value)) {
        // The number is quoted up to kQuotedDigits characters: a request of a megabyte of
        // digits is not echoed back whole.
        const std::string_view number = data_.substr(begin, pos_ - begin);
        const std::string quoted = number.size() <= kQuotedDigits
                                       ? std::string(number)
                                       : std::string(number.substr(0, kQuotedDigits)) + "\xE2\x80\xA6";
        return fail(PathDataErrorKind::out_of_range, begin,
                    "the number " + quoted + " is beyond the double range");
      }
    } else if (ec != std::errc{} || end != last) {
      return fail(PathDataErrorKind::syntax, begin, "expected a number");
    }
    return true;
  }

  /// The numbers of one repetition of `command`'s arguments, separated by comma-wsp (or by
  /// nothing where a sign or point begins the next), then the segment they draw.
  bool arguments(char command, bool first_group, std::size_t offset) {
    const int count = argument_count(command);
    std::array<double, 7> a{};
    for (int k = 0; k < count; ++k) {
      if (k > 0) {
        skip_wsp();
        if (!at_end() && data_[pos_] == ',') {
          ++pos_;
          skip_wsp();
        }
      }
      // The large-arc and sweep flags of an arc (its 4th and 5th arguments) are one
      // character each, so "00" or "11" is two flags, as in "a1 1 0 00 1 1".
      if ((command == 'A' || command == 'a') && (k == 3 || k == 4)) {
        if (!flag(a[static_cast<std::size_t>(k)])) return false;
        continue;
      }
      if (!number(a[static_cast<std::size_t>(k)])) return false;
    }
    const bool relative = command >= 'a';
    const Point2 base = relative ? current_ : Point2{0.0, 0.0};
    const auto at = [&](std::size_t k) { return Point2{base.x + a[k], base.y + a[k + 1]}; };
    if (command == 'A' || command == 'a') {
      return elliptical_arc(EllipticalArc{current_, at(5), a[0], a[1], a[2], a[3] != 0.0, a[4] != 0.0},
                            offset);
    }
    switch (command) {
      case 'M': case 'm':
        // Only the first pair moves; later pairs are implicit line commands.
        if (first_group) return move_to(at(0), offset);
        return segment({current_, at(0)}, Previous::other, offset);
      case 'L': case 'l':
        return segment({current_, at(0)}, Previous::other, offset);
      case 'H': case 'h':
        return segment({current_, {base.x + a[0], current_.y}}, Previous::other, offset);
      case 'V': case 'v':
        return segment({current_, {current_.x, base.y + a[0]}}, Previous::other, offset);
      case 'C': case 'c':
        return segment({current_, at(0), at(2), at(4)}, Previous::cubic, offset);
      case 'S': case 's':
        return segment({current_, reflected(Previous::cubic), at(0), at(2)}, Previous::cubic,
                       offset);
      case 'Q': case 'q':
        return segment({current_, at(0), at(2)}, Previous::quadratic, offset);
      case 'T': case 't':
        return segment({current_, reflected(Previous::quadratic), at(0)}, Previous::quadratic,
                       offset);
      default:
        return fail(PathDataErrorKind::syntax, offset, "expected a command letter");
    }
  }

  /// A flag argument of an arc at pos_: the character 0 or 1.
  bool flag(double& value) {
    if (at_end() || (data_[pos_] != '0' && data_[pos_] != '1')) {
      return fail(PathDataErrorKind::syntax, pos_,
                  at_end() ? std::string("expected a flag (0 or 1), found the end of the data")
                           : "expected a flag (0 or 1), found " + describe(data_[pos_]));
    }
    value = data_[pos_] == '1' ? 1.0 : 0.0;
    ++pos_;
    return true;
  }

  /// The segments of an arc (core/path/elliptical_arc.hpp): none when it ends where it
  /// starts, a line for a zero radius, else cubics within the tolerance. S and T after it
  /// reflect nothing (it is not of their family).
  bool elliptical_arc(const EllipticalArc& arc, std::size_t offset) {
    if (!core::is_finite(arc.to)) {
      return fail(PathDataErrorKind::out_of_range, offset,
                  "the coordinates leave the double range");
    }
    const std::size_t room =
        max_segments_ - std::min(max_segments_, path_.segments.size());
    ArcSegments made = arc_to_cubics(arc, arc_tolerance_, room);
    if (made.status == ArcStatus::too_many_pieces) {
      return fail(PathDataErrorKind::too_many_segments, offset,
                  "more than " + std::to_string(max_segments_) +
                      " segments (an elliptical arc becomes cubics within its tolerance: a "
                      "larger arc_tolerance needs fewer)");
    }
    if (made.status == ArcStatus::out_of_range) {
      return fail(PathDataErrorKind::out_of_range, offset,
                  "the arc's control points leave the double range");
    }
    path_.arc_tolerance = std::max(path_.arc_tolerance.value_or(0.0), made.tolerance);
    previous_ = Previous::other;
    for (core::Curve& piece : made.segments) {
      if (!segment(std::vector<Point2>(piece.points().begin(), piece.points().end()),
                   Previous::other, offset)) {
        return false;
      }
    }
    return true;
  }

  /// The first control point of S (family cubic) or T (family quadratic): the reflection of
  /// the previous segment's last inner control point about the current point, 2 P - C,
  /// when the previous segment is of the same family; else the current point.
  [[nodiscard]] Point2 reflected(Previous family) const {
    if (previous_ != family) return current_;
    return 2.0 * current_ - reflect_from_;
  }

  bool move_to(Point2 p, std::size_t offset) {
    if (!core::is_finite(p)) {
      return fail(PathDataErrorKind::out_of_range, offset,
                  "the coordinates leave the double range");
    }
    end_subpath();
    current_ = p;
    start_ = p;
    moved_ = true;
    previous_ = Previous::other;
    return true;
  }

  bool segment(std::vector<Point2> points, Previous kind, std::size_t offset) {
    for (const Point2 p : points) {
      if (!core::is_finite(p)) {
        return fail(PathDataErrorKind::out_of_range, offset,
                    "the coordinates leave the double range");
      }
    }
    if (path_.segments.size() >= max_segments_) {
      return fail(PathDataErrorKind::too_many_segments, offset,
                  "more than " + std::to_string(max_segments_) + " segments");
    }
    if (!subpath_open_) {
      subpath_first_ = path_.segments.size();
      subpath_open_ = true;
    }
    current_ = points.back();
    moved_ = false;
    previous_ = kind;
    if (kind != Previous::other) reflect_from_ = points[points.size() - 2];
    path_.segments.emplace_back(std::move(points));
    return true;
  }

  bool close_subpath(std::size_t offset) {
    // A line back to the start where the current point is elsewhere; one of zero length where
    // nothing was drawn since the moveto (M x y Z: a zero-length subpath, which SVG strokes
    // as a dot under round and square caps).
    if ((subpath_open_ && !(current_ == start_)) || (!subpath_open_ && moved_)) {
      if (!segment({current_, start_}, Previous::other, offset)) return false;
      closing_lines_.push_back(path_.segments.size() - 1);
    }
    moved_ = false;
    end_subpath();
    current_ = start_;
    previous_ = Previous::other;
    return true;
  }

  /// Records the subpath being drawn, if it drew anything.
  void end_subpath() {
    if (!subpath_open_) return;
    subpath_open_ = false;
    const std::size_t count = path_.segments.size() - subpath_first_;
    const bool closed = path_.segments.back().back() == path_.segments[subpath_first_].front();
    path_.subpaths.push_back(Subpath{subpath_first_, count, closed});
  }

  std::string_view data_;
  std::size_t max_segments_;
  std::optional<double> arc_tolerance_;
  std::size_t pos_ = 0;
  std::optional<PathDataError> error_;
  Path path_;
  std::vector<std::size_t> closing_lines_;
  Point2 current_{};
  Point2 start_{};
  std::size_t subpath_first_ = 0;
  bool subpath_open_ = false;
  bool moved_ = false;  // a moveto and nothing drawn since
  Previous previous_ = Previous::other;
  Point2 reflect_from_{};
};

}  // namespace

PathDataParse parse_svg_path_data(std::string_view data, std::size_t max_segments,
                                  std::optional<double> arc_tolerance) {
  return PathDataParser(data, max_segments, arc_tolerance).run();
}

}  // namespace bezier::path
