#pragma once

// Paths for the path tests, written as SVG path data.

#include <gtest/gtest.h>

#include <string_view>
#include <utility>

#include "core/path/path.hpp"
#include "core/path/svg_path_data.hpp"

namespace bezier::test {

/// The path that `data` spells (at most 1000 segments); data that does not parse fails the
/// calling test.
[[nodiscard]] inline path::Path parsed_path(std::string_view data) {
  path::PathDataParse parse = path::parse_svg_path_data(data, 1000);
  EXPECT_FALSE(parse.error) << data;
  return std::move(parse.path);
}

}  // namespace bezier::test
