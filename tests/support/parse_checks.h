#pragma once
// Checking a scene text's messages in a test case: the error a mistake gets, at its token.
#include <doctest/doctest.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>

#include "scene_parse.h"

namespace bsim::test {

/// Every diagnostic of `r`, formatted as the programs print them, one per line.
inline std::string all_messages(const ParseResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += format_diagnostic(d, "scene") + "\n";
  return out;
}

/// `text` gives no scene, and its first error is at line:column and contains every one of `parts`.
inline void expect_error(const std::string& text, int line, int column, std::initializer_list<std::string_view> parts,
                         ParseOptions options = {}) {
  const ParseResult r = parse_scene(text, "t", options);
  INFO("scene:\n" << text << "diagnostics:\n" << all_messages(r));
  CHECK_FALSE(r.scene.has_value());
  const auto first = std::find_if(r.diagnostics.begin(), r.diagnostics.end(),
                                  [](const Diagnostic& d) { return d.severity == Severity::error; });
  REQUIRE(first != r.diagnostics.end());
  CHECK(first->loc.line == line);
  CHECK(first->loc.column == column);
  for (std::string_view part : parts) CHECK(first->message.find(part) != std::string::npos);
}

/// As above, with one part.
inline void expect_error(const std::string& text, int line, int column, std::string_view part,
                         ParseOptions options = {}) {
  expect_error(text, line, column, {part}, options);
}

}  // namespace bsim::test
