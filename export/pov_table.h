#pragma once
// The shared POV-Ray include every frame file reads: the table built by CSG from the scene's
// cushions and pockets, the balls, the cue stick, the room and the lights for a quality preset.
#include <ostream>
#include <string_view>

#include "export_options.h"
#include "scene.h"

namespace bsim {

/// File name of the shared include, beside the frame files.
inline constexpr std::string_view kPovIncludeName = "billiards.inc";

/// Writes the include: first the scene's numbers (cushion nose lines, pockets, ball radius,
/// quality), the table description's (table.h: cushion profile, wood, sights, floor) and the balls'
/// colours (ball_look.h), then the fixed models that build on them (pov_models_text()).
void write_pov_include(const Scene& scene, Quality quality, std::ostream& out);

/// The fixed part of the include: materials, the table's CSG macros, balls, cue stick, room, lights.
/// The files export/pov/*.inc, compiled in by the build (export/pov/README.md).
std::string_view pov_models_text();

}  // namespace bsim
