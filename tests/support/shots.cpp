#include "shots.h"

#include <doctest/doctest.h>

#include <string>

namespace bsim::test {

namespace {
std::string listed(const std::vector<Diagnostic>& diagnostics, std::string_view name) {
  std::string text;
  for (const Diagnostic& d : diagnostics) text += format_diagnostic(d, std::string(name) + ".scn") + "\n";
  return text;
}
}  // namespace

std::unique_ptr<Shot> load_scene(std::string_view text, std::string_view name) {
  ShotResult result = load_shot(text, name);
  REQUIRE_MESSAGE(result.scripted(), "the scene does not load:\n" << listed(result.diagnostics, name));
  return std::move(result.shot);
}

std::unique_ptr<Shot> load_clean(std::string_view text, std::string_view name) {
  ShotResult result = load_shot(text, name);
  CHECK_MESSAGE(result.diagnostics.empty(), "the scene should load without a message:\n"
                                                << listed(result.diagnostics, name));
  REQUIRE_MESSAGE(result.scripted(), "the scene does not load");
  return std::move(result.shot);
}

}  // namespace bsim::test
