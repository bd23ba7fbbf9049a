#pragma once

// The body of a POST /batch built from its items, for the tests and the fuzz target of the
// batch route.

#include <string>
#include <vector>

namespace bezier::test {

/// One item of a batch: the path it names and its body, JSON text (or not) that goes into
/// the batch as it is, so that a test controls its every byte.
struct BatchItem {
  std::string path;
  std::string body;
};

/// {"requests":[{"path":"...","body":...}, ...]}, without blanks.
inline std::string batch_body(const std::vector<BatchItem>& items) {
  std::string text = R"({"requests":[)";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += ',';
    text += R"({"path":")" + items[i].path + R"(","body":)" + items[i].body + '}';
  }
  return text + "]}";
}

}  // namespace bezier::test
