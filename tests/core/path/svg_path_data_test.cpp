#include "core/path/svg_path_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace bezier::path {
namespace {

using core::Curve;
using core::Point2;

constexpr std::size_t kNoLimit = std::numeric_limits<std::size_t>::max();

Path parsed(std::string_view data) {
  PathDataParse parse = parse_svg_path_data(data, kNoLimit);
  EXPECT_FALSE(parse.error) << data << ": at " << parse.error->offset << ": "
                            << parse.error->message;
  return std::move(parse.path);
}

PathDataError error_of(std::string_view data, std::size_t max_segments = kNoLimit) {
  const PathDataParse parse = parse_svg_path_data(data, max_segments);
  EXPECT_TRUE(parse.error) << data;
  EXPECT_TRUE(parse.path.segments.empty());
  return parse.error.value_or(PathDataError{});
}

Curve line(Point2 a, Point2 b) { return Curve({a, b}); }
Curve quad(Point2 a, Point2 b, Point2 c) { return Curve({a, b, c}); }
Curve cubic(Point2 a, Point2 b, Point2 c, Point2 d) { return Curve({a, b, c, d}); }

std::vector<Curve> segments_of(std::string_view data) { return parsed(data).segments; }

TEST(SvgPathData, EmptyDataAndMovetosAloneHaveNoSegments) {
  for (const char* data : {"", "   \t\n", "M1 1", "m1 1 M2 2", "M1 1 A1 1 0 0 1 1 1"}) {
    const Path p = parsed(data);
    EXPECT_TRUE(p.segments.empty()) << data;
    EXPECT_TRUE(p.subpaths.empty()) << data;
  }
}

TEST(SvgPathData, ZRightAfterAMovetoIsAClosingLineOfZeroLength) {
  // A zero-length subpath (SVG 2 strokes it as a dot under round and square caps); a
  // second Z draws nothing more, and a moveto before the last one is still left out.
  for (const auto& [data, at] :
       {std::pair{"M1 1 Z", Point2{1, 1}}, std::pair{"m1 1 z z", Point2{1, 1}},
        std::pair{"M0 0 M2 3 Z", Point2{2, 3}}, std::pair{"M2 3 A1 1 0 0 1 2 3 z", Point2{2, 3}}}) {
    const PathDataParse parse = parse_svg_path_data(data, 100);
    ASSERT_FALSE(parse.error) << data;
    EXPECT_EQ(parse.path.segments, std::vector<Curve>{line(at, at)}) << data;
    ASSERT_EQ(parse.path.subpaths.size(), 1u) << data;
    EXPECT_TRUE(parse.path.subpaths[0].closed) << data;
    EXPECT_EQ(parse.closing_lines, std::vector<std::size_t>{0}) << data;
  }
  // Two such subpaths, and one after a closed subpath (its Z starts nothing).
  EXPECT_EQ(segments_of("M1 1zM2 2z"),
            (std::vector<Curve>{line({1, 1}, {1, 1}), line({2, 2}, {2, 2})}));
  EXPECT_EQ(segments_of("M0 0 L1 0 L0 0 Z Z"),
            (std::vector<Curve>{line({0, 0}, {1, 0}), line({1, 0}, {0, 0})}));
}

TEST(SvgPathData, LineCommandsAbsoluteAndRelative) {
  EXPECT_EQ(segments_of("M1 2 L3 4"), std::vector<Curve>{line({1, 2}, {3, 4})});
  EXPECT_EQ(segments_of("M1 2 l3 4"), std::vector<Curve>{line({1, 2}, {4, 6})});
  EXPECT_EQ(segments_of("M1 2 H5"), std::vector<Curve>{line({1, 2}, {5, 2})});
  EXPECT_EQ(segments_of("M1 2 h5"), std::vector<Curve>{line({1, 2}, {6, 2})});
  EXPECT_EQ(segments_of("M1 2 V5"), std::vector<Curve>{line({1, 2}, {1, 5})});
  EXPECT_EQ(segments_of("M1 2 v5"), std::vector<Curve>{line({1, 2}, {1, 7})});
}

TEST(SvgPathData, CurveCommandsAbsoluteAndRelative) {
  EXPECT_EQ(segments_of("M1 1 C2 3 4 5 6 7"),
            std::vector<Curve>{cubic({1, 1}, {2, 3}, {4, 5}, {6, 7})});
  EXPECT_EQ(segments_of("M1 1 c2 3 4 5 6 7"),
            std::vector<Curve>{cubic({1, 1}, {3, 4}, {5, 6}, {7, 8})});
  EXPECT_EQ(segments_of("M1 1 Q2 3 4 5"), std::vector<Curve>{quad({1, 1}, {2, 3}, {4, 5})});
  EXPECT_EQ(segments_of("M1 1 q2 3 4 5"), std::vector<Curve>{quad({1, 1}, {3, 4}, {5, 6})});
}

TEST(SvgPathData, LeadingRelativeMovetoIsFromTheOrigin) {
  EXPECT_EQ(segments_of("m1 2 L3 4"), std::vector<Curve>{line({1, 2}, {3, 4})});
}

TEST(SvgPathData, MovetoRepeatsAreImplicitLines) {
  // SVG 2 §9.3.3: further pairs after M are L, after m they are l.
  EXPECT_EQ(segments_of("M0 0 1 1 2 0"),
            (std::vector<Curve>{line({0, 0}, {1, 1}), line({1, 1}, {2, 0})}));
  EXPECT_EQ(segments_of("m1 1 2 2 1 -1"),
            (std::vector<Curve>{line({1, 1}, {3, 3}), line({3, 3}, {4, 2})}));
}

TEST(SvgPathData, EveryCommandRepeatsWithoutItsLetter) {
  EXPECT_EQ(segments_of("M0 0 L1 0 1 1"),
            (std::vector<Curve>{line({0, 0}, {1, 0}), line({1, 0}, {1, 1})}));
  EXPECT_EQ(segments_of("M0 0 h1 2"),
            (std::vector<Curve>{line({0, 0}, {1, 0}), line({1, 0}, {3, 0})}));
  EXPECT_EQ(segments_of("M0 0 V1 3"),
            (std::vector<Curve>{line({0, 0}, {0, 1}), line({0, 1}, {0, 3})}));
  EXPECT_EQ(segments_of("M0 0 c1 1 2 1 3 0 1 -1 2 -1 3 0"),
            (std::vector<Curve>{cubic({0, 0}, {1, 1}, {2, 1}, {3, 0}),
                                cubic({3, 0}, {4, -1}, {5, -1}, {6, 0})}));
  EXPECT_EQ(segments_of("M0 0 Q1 1 2 0 3 -1 4 0"),
            (std::vector<Curve>{quad({0, 0}, {1, 1}, {2, 0}), quad({2, 0}, {3, -1}, {4, 0})}));
}

TEST(SvgPathData, CompactNumbers) {
  // The example: a sign or a second point ends a number without a separator.
  EXPECT_EQ(segments_of("M0,0C.5-.5,1 1,2 0"),
            std::vector<Curve>{cubic({0, 0}, {0.5, -0.5}, {1, 1}, {2, 0})});
  EXPECT_EQ(segments_of("M.5.5L-.5-.5"), std::vector<Curve>{line({0.5, 0.5}, {-0.5, -0.5})});
  EXPECT_EQ(segments_of("M1e-3,2E+2L+1.,-0.25e1"),
            std::vector<Curve>{line({0.001, 200}, {1, -2.5})});
  EXPECT_EQ(segments_of("M0-1l2-3"), std::vector<Curve>{line({0, -1}, {2, -4})});
  EXPECT_EQ(segments_of("M1.5e1.5L0 0"), std::vector<Curve>{line({15, 0.5}, {0, 0})});
}

TEST(SvgPathData, DecimalsRoundAsStrtodRoundsThem) {
  const std::vector<Curve> s = segments_of("M0.1 0.7L123456.789e-3 3.14159265358979323846");
  EXPECT_EQ(s, std::vector<Curve>{line({std::strtod("0.1", nullptr), std::strtod("0.7", nullptr)},
                                       {std::strtod("123456.789e-3", nullptr),
                                        std::strtod("3.14159265358979323846", nullptr)})});
}

TEST(SvgPathData, SeparatorsAreWhitespaceAndAtMostOneComma) {
  const std::vector<Curve> expected{line({1, 2}, {3, 4}), line({3, 4}, {5, 6})};
  for (const char* data : {"M1 2L3 4 5 6", "M1,2L3,4,5,6", " \t\nM 1 , 2 L 3\r\n4\f5 ,6 ",
                           "M1,2 L3 ,4 , 5 6"}) {
    EXPECT_EQ(segments_of(data), expected) << data;
  }
}

TEST(SvgPathData, SmoothCubicReflectsThePreviousCubicsSecondControlPoint) {
  // C ends at (3, 0) with second control point (2, 1): S's first control point is its
  // reflection 2 (3, 0) - (2, 1) = (4, -1). The next S reflects the first S's (5, -2).
  EXPECT_EQ(segments_of("M0 0 C1 1 2 1 3 0 S5 -2 6 0 S8 1 9 0"),
            (std::vector<Curve>{cubic({0, 0}, {1, 1}, {2, 1}, {3, 0}),
                                cubic({3, 0}, {4, -1}, {5, -2}, {6, 0}),
                                cubic({6, 0}, {7, 2}, {8, 1}, {9, 0})}));
  // Relative: the same outline.
  EXPECT_EQ(segments_of("m0 0 c1 1 2 1 3 0 s2 -2 3 0 s2 1 3 0"),
            segments_of("M0 0 C1 1 2 1 3 0 S5 -2 6 0 S8 1 9 0"));
}

TEST(SvgPathData, SmoothCubicAfterAnythingElseStartsAtTheCurrentPoint) {
  EXPECT_EQ(segments_of("M0 0 L1 0 S2 1 3 0"),
            (std::vector<Curve>{line({0, 0}, {1, 0}), cubic({1, 0}, {1, 0}, {2, 1}, {3, 0})}));
  EXPECT_EQ(segments_of("M0 0 Q1 1 2 0 S3 1 4 0"),
            (std::vector<Curve>{quad({0, 0}, {1, 1}, {2, 0}),
                                cubic({2, 0}, {2, 0}, {3, 1}, {4, 0})}));
  EXPECT_EQ(segments_of("M5 5 S6 6 7 5"),
            std::vector<Curve>{cubic({5, 5}, {5, 5}, {6, 6}, {7, 5})});
  // After Z the previous command is Z, not the cubic before it.
  const std::vector<Curve> s = segments_of("M0 0 C1 1 2 1 3 0 Z S1 -1 0 -2");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[2], cubic({0, 0}, {0, 0}, {1, -1}, {0, -2}));
}

TEST(SvgPathData, SmoothQuadraticReflectsThroughAChainOfT) {
  // Q's control (1, 1) about (2, 0) gives (3, -1); that one about (4, 0) gives (5, 1).
  EXPECT_EQ(segments_of("M0 0 Q1 1 2 0 T4 0 T6 0"),
            (std::vector<Curve>{quad({0, 0}, {1, 1}, {2, 0}), quad({2, 0}, {3, -1}, {4, 0}),
                                quad({4, 0}, {5, 1}, {6, 0})}));
  EXPECT_EQ(segments_of("M0 0 q1 1 2 0 t2 0 2 0"), segments_of("M0 0 Q1 1 2 0 T4 0 T6 0"));
}

TEST(SvgPathData, SmoothQuadraticAfterAnythingElseStartsAtTheCurrentPoint) {
  EXPECT_EQ(segments_of("M0 0 C1 1 2 1 3 0 T4 0"),
            (std::vector<Curve>{cubic({0, 0}, {1, 1}, {2, 1}, {3, 0}),
                                quad({3, 0}, {3, 0}, {4, 0})}));
  EXPECT_EQ(segments_of("M1 2 T3 4"), std::vector<Curve>{quad({1, 2}, {1, 2}, {3, 4})});
}

TEST(SvgPathData, CloseAddsTheClosingLineWhenItHasLength) {
  const Path open_end = parsed("M0 0 L2 0 L2 2 Z");
  EXPECT_EQ(open_end.segments, (std::vector<Curve>{line({0, 0}, {2, 0}), line({2, 0}, {2, 2}),
                                                   line({2, 2}, {0, 0})}));
  ASSERT_EQ(open_end.subpaths.size(), 1u);
  EXPECT_EQ(open_end.subpaths[0].segment_count, 3u);
  EXPECT_TRUE(open_end.subpaths[0].closed);

  const Path at_start = parsed("M0 0 L2 0 L2 2 L0 0 z");
  EXPECT_EQ(at_start.segments.size(), 3u);
  EXPECT_TRUE(at_start.subpaths[0].closed);
}

TEST(SvgPathData, SubpathEndingAtItsStartIsClosedWithoutZ) {
  const Path p = parsed("M0 0 C1 1 -1 1 0 0 M5 5 L6 6");
  ASSERT_EQ(p.subpaths.size(), 2u);
  EXPECT_TRUE(p.subpaths[0].closed);
  EXPECT_FALSE(p.subpaths[1].closed);
}

TEST(SvgPathData, SeveralSubpathsInDrawingOrder) {
  const Path p = parsed("M0 0 L1 0 L1 1 Z M5 5 l1 0 m2 2 h1 v1 z");
  EXPECT_EQ(p.segments,
            (std::vector<Curve>{line({0, 0}, {1, 0}), line({1, 0}, {1, 1}), line({1, 1}, {0, 0}),
                                line({5, 5}, {6, 5}), line({8, 7}, {9, 7}), line({9, 7}, {9, 8}),
                                line({9, 8}, {8, 7})}));
  ASSERT_EQ(p.subpaths.size(), 3u);
  EXPECT_EQ(p.subpaths[0].first_segment, 0u);
  EXPECT_EQ(p.subpaths[0].segment_count, 3u);
  EXPECT_TRUE(p.subpaths[0].closed);
  EXPECT_EQ(p.subpaths[1].first_segment, 3u);
  EXPECT_EQ(p.subpaths[1].segment_count, 1u);
  EXPECT_FALSE(p.subpaths[1].closed);
  EXPECT_EQ(p.subpaths[2].first_segment, 4u);
  EXPECT_EQ(p.subpaths[2].segment_count, 3u);
  EXPECT_TRUE(p.subpaths[2].closed);
}

TEST(SvgPathData, DrawingAfterCloseStartsAgainAtTheSubpathsStart) {
  // SVG 2 §9.3.4: after Z the current point is the subpath's start, and a command other
  // than M begins a new subpath there; relative coordinates are from that point.
  const Path p = parsed("M1 1 L3 1 L3 3 Z l0 -2");
  EXPECT_EQ(p.segments.back(), line({1, 1}, {1, -1}));
  ASSERT_EQ(p.subpaths.size(), 2u);
  EXPECT_EQ(p.subpaths[1].first_segment, 3u);
  EXPECT_FALSE(p.subpaths[1].closed);
  // A relative moveto after Z is also from the start point.
  EXPECT_EQ(segments_of("M1 1 L3 1 z m1 1 l1 0").back(), line({2, 2}, {3, 2}));
}

TEST(SvgPathData, ZeroLengthSegmentsAreKept) {
  EXPECT_EQ(segments_of("M1 1 L1 1 h0"),
            (std::vector<Curve>{line({1, 1}, {1, 1}), line({1, 1}, {1, 1})}));
}

TEST(SvgPathData, NumbersBelowTheDoubleRangeRoundToZero) {
  EXPECT_EQ(segments_of("M1e-400 0 L1 0"), std::vector<Curve>{line({0, 0}, {1, 0})});
}

struct ErrorCase {
  const char* data;
  std::size_t offset;
  PathDataErrorKind kind;
  const char* message_part;
};

TEST(SvgPathData, ErrorsNameTheirOffsetAndWhatWasExpected) {
  using K = PathDataErrorKind;
  const ErrorCase cases[] = {
      {"L1 1", 0, K::syntax, "expected a moveto command"},
      {"  1 1", 2, K::syntax, "expected a moveto command"},
      {"M0 0 A1 1 0 2 1 2 2", 12, K::syntax, "expected a flag (0 or 1), found '2'"},
      {"M0 0 a1 1 0 0", 13, K::syntax, "expected a flag (0 or 1), found the end"},
      {"M0 0 A1 1 0 0 1 2", 17, K::syntax, "expected a number, found the end"},
      {"M0 0 A1 1 0 .5 1 2 2", 12, K::syntax, "expected a flag (0 or 1), found '.'"},
      {"M0 0 A1.7e308 1 0 1 1 1e308 0", 5, K::out_of_range, "control points leave"},
      {"M0,0,L1,1", 5, K::syntax, "expected a number after ','"},
      {"M0 0 L1 1,", 10, K::syntax, "expected a number after ','"},
      {"M0 0 L1", 7, K::syntax, "expected a number, found the end of the data"},
      {"M0 0 L1 1 2", 11, K::syntax, "expected a number, found the end"},
      {"M0 0 L,1 1", 6, K::syntax, "expected a number, found ','"},
      {"M0 0 L1,,1", 8, K::syntax, "expected a number, found ','"},
      {"M0 0 L1e 1", 8, K::syntax, "expected a digit of the exponent"},
      {"M0 0 L1e+", 9, K::syntax, "expected a digit of the exponent, found the end"},
      {"M0 0 L- 1", 7, K::syntax, "expected a digit, found byte 0x20"},
      {"M0 0 L. 1", 7, K::syntax, "expected a digit"},
      {"M0 0 L+-1 1", 7, K::syntax, "expected a digit, found '-'"},
      {"M0 0 X1 1", 5, K::syntax, "expected a command letter"},
      {"M0 0 L1 1 Z 3 3", 12, K::syntax, "expected a command letter"},
      {"M0 0 L1 1 \xC3\xA9", 10, K::syntax, "found byte 0xC3"},
      {"M0 0 L1 1 e", 10, K::syntax, "found 'e'"},
      {"M1e400 0", 1, K::out_of_range, "1e400 is beyond the double range"},
      {"M0 0 L0 -1e309", 8, K::out_of_range, "beyond the double range"},
      {"M1e308 0 l1e308 0", 9, K::out_of_range, "coordinates leave the double range"},
      {"M1e308 0 L1e308 1 m1e308 0", 18, K::out_of_range, "coordinates leave the double range"},
  };
  for (const ErrorCase& c : cases) {
    const PathDataError e = error_of(c.data);
    EXPECT_EQ(e.offset, c.offset) << c.data << ": " << e.message;
    EXPECT_EQ(e.kind, c.kind) << c.data << ": " << e.message;
    EXPECT_NE(e.message.find(c.message_part), std::string::npos) << c.data << ": " << e.message;
  }
}

TEST(SvgPathData, SegmentLimitStopsAtTheFirstSegmentTooMany) {
  // Implicit repeats: the third line is drawn by the pair at offset 14.
  const PathDataError e = error_of("M0 0 L1 1 2 2 3 3", 2);
  EXPECT_EQ(e.kind, PathDataErrorKind::too_many_segments);
  EXPECT_EQ(e.offset, 14u);
  EXPECT_NE(e.message.find("more than 2 segments"), std::string::npos);
  // A closing line counts: it is drawn by the Z at offset 10.
  EXPECT_EQ(error_of("M0 0 L1 1 Z", 1).offset, 10u);
  EXPECT_FALSE(parse_svg_path_data("M0 0 L1 1 2 2", 2).error);
}

// ---- Random outlines: the absolute and relative spellings, compact or spaced, agree ----

/// A coordinate on the grid of multiples of 1/8 in [-4, 4), many of them written ".5" in the
/// compact spelling: sums and differences of such numbers are exact, so the absolute and
/// relative spellings describe the same doubles.
double grid(test::Mulberry32& rng) { return std::floor(rng.uniform(-32, 32)) / 8; }

std::string number_text(double v, bool compact) {
  // Shortest spelling, written without a leading zero in compact mode (".5", "-.25").
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (compact) {
    if (s.rfind("0.", 0) == 0) s.erase(0, 1);
    if (s.rfind("-0.", 0) == 0) s.erase(1, 1);
  }
  return s;
}

/// Appends a command's numbers as a writer of one style would: spaced, with commas inside
/// pairs, or compact, with a space only where the next number would otherwise continue the
/// one before (it starts with a digit, or with a point after a number that has one).
void append_numbers(std::string& out, const std::vector<double>& values, bool compact) {
  std::string previous;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string text = number_text(values[i], compact);
    if (!compact) {
      out += (i % 2 == 1) ? "," : " ";
    } else if (i > 0) {
      const bool delimits_itself =
          text[0] == '-' || (text[0] == '.' && previous.find('.') != std::string::npos);
      if (!delimits_itself) out += ' ';
    }
    out += text;
    previous = text;
  }
}

TEST(SvgPathData, RandomOutlinesSpelledAbsoluteOrRelativeAgree) {
  test::Mulberry32 rng(21);
  for (int round = 0; round < 300; ++round) {
    const bool compact = round % 2 == 1;
    std::string absolute = "M";
    std::string relative = "m";
    Point2 current{grid(rng), grid(rng)};
    Point2 start = current;
    append_numbers(absolute, {current.x, current.y}, compact);
    append_numbers(relative, {current.x, current.y}, compact);
    const int commands = 1 + static_cast<int>(rng.next() * 12);
    for (int k = 0; k < commands; ++k) {
      static constexpr char kLetters[] = {'L', 'H', 'V', 'C', 'S', 'Q', 'T', 'Z', 'M'};
      const char letter = kLetters[static_cast<int>(rng.next() * 9)];
      // The points the command's numbers give, in order (S and T leave out the reflected one).
      const int count = letter == 'C' ? 3 : (letter == 'S' || letter == 'Q') ? 2 : letter == 'Z' ? 0 : 1;
      std::vector<Point2> points;
      for (int i = 0; i < count; ++i) points.push_back({grid(rng), grid(rng)});
      if (letter == 'H') points[0].y = current.y;
      if (letter == 'V') points[0].x = current.x;
      absolute += letter;
      relative += static_cast<char>(letter - 'A' + 'a');
      std::vector<double> abs_numbers;
      std::vector<double> rel_numbers;
      for (const Point2 p : points) {
        if (letter == 'H') {
          abs_numbers.push_back(p.x);
          rel_numbers.push_back(p.x - current.x);
        } else if (letter == 'V') {
          abs_numbers.push_back(p.y);
          rel_numbers.push_back(p.y - current.y);
        } else {
          abs_numbers.insert(abs_numbers.end(), {p.x, p.y});
          rel_numbers.insert(rel_numbers.end(), {p.x - current.x, p.y - current.y});
        }
      }
      append_numbers(absolute, abs_numbers, compact);
      append_numbers(relative, rel_numbers, compact);
      if (letter == 'Z') current = start;
      else current = points.back();
      if (letter == 'M') start = current;
      if (!compact) {
        absolute += ' ';
        relative += ' ';
      }
    }
    const PathDataParse a = parse_svg_path_data(absolute, kNoLimit);
    const PathDataParse r = parse_svg_path_data(relative, kNoLimit);
    ASSERT_FALSE(a.error) << absolute << " at " << a.error->offset << ": " << a.error->message;
    ASSERT_FALSE(r.error) << relative << " at " << r.error->offset << ": " << r.error->message;
    EXPECT_EQ(a.path.segments, r.path.segments) << absolute << "\n" << relative;
    ASSERT_EQ(a.path.subpaths.size(), r.path.subpaths.size());
    // Every subpath is a chain: each segment starts where the previous one ends.
    for (const Subpath& sub : a.path.subpaths) {
      for (std::size_t i = 1; i < sub.segment_count; ++i) {
        EXPECT_EQ(a.path.segments[sub.first_segment + i].front(),
                  a.path.segments[sub.first_segment + i - 1].back());
      }
    }
  }
}

}  // namespace
}  // namespace bezier::path

namespace bezier::path {
namespace {

TEST(SvgPathData, ClosingLinesAreTheLinesZAdds) {
  // Z after a drawn line back to the start adds nothing; z elsewhere adds its line.
  const PathDataParse p = parse_svg_path_data("M0 0 L1 0 L0 0 Z M5 5 h1 v1 z L9 9 z", kNoLimit);
  ASSERT_FALSE(p.error);
  // Segments: 0 (1,0) 1 back to (0,0), 2 h1, 3 v1, 4 closing, 5 L9 9 (from (5, 5)), 6 closing.
  EXPECT_EQ(p.closing_lines, (std::vector<std::size_t>{4, 6}));
  EXPECT_EQ(p.path.segments[4], Curve({{6, 6}, {5, 5}}));
}

}  // namespace
}  // namespace bezier::path
