#pragma once
// Scene text -> Scene, or located diagnostics. Never exits, never throws on bad input.
#include <optional>
#include <string_view>
#include <vector>

#include "diagnostics.h"
#include "scene.h"

namespace bsim {

struct ParseOptions {
  bool strict = false;  ///< reject the extensions (comments, spin, pocket, param)
};

struct ParseResult {
  std::optional<Scene> scene;           ///< present when there is no error
  std::vector<Diagnostic> diagnostics;  ///< errors and warnings, in file order
};

/// `name` becomes Scene::name (the file stem).
ParseResult parse_scene(std::string_view text, std::string_view name, const ParseOptions& options = {});

}  // namespace bsim
