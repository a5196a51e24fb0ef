#pragma once
#include <string_view>

namespace bsim {
/// The text of scenes/break.scn, compiled in: the scene used when none is given.
std::string_view builtin_scene_text();
inline constexpr std::string_view kBuiltinSceneName = "break";
}  // namespace bsim
