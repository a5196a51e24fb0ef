// PLACEHOLDER until the parser lands.
#include "scene_parse.h"
namespace bsim {
ParseResult parse_scene(std::string_view, std::string_view name, const ParseOptions&) {
  ParseResult r;
  r.diagnostics.push_back({Severity::error, {1, 1}, "the scene parser is not built yet"});
  (void)name;
  return r;
}
}  // namespace bsim
