#pragma once
// The GLSL programs of the 3D view: one per material (table, ball, cue, flat colour, soft shadow).
#include <string>

namespace bsim {

enum class Material { table = 0, ball = 1, cue = 2, flat = 3, shadow = 4 };

inline constexpr int kMaterialCount = 5;

/// Compiles and links the program for one material. Returns 0 and sets `error` on failure.
unsigned build_scene_program(Material material, std::string& error);

}  // namespace bsim
