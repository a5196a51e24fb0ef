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

/// How the frames look. `photo` is what billiards-export renders; `classic` is the look before it
/// (flat light, a table in a dark box), kept so that the render benchmark can time the two side by
/// side and make the README's before-and-after gallery.
enum class Look { photo, classic };

/// Writes the include: first the scene's numbers (cushion nose lines, pockets, ball radius,
/// quality), the table description's (table.h: cushion profile, wood, sights, floor) and the balls'
/// colours (ball_look.h), then the fixed models that build on them (pov_models_text()).
void write_pov_include(const Scene& scene, Quality quality, std::ostream& out, Look look = Look::photo);

/// The fixed part of the include: materials, the table's CSG macros, balls, cue stick, room, lights.
std::string_view pov_models_text();
/// The same for the classic look.
std::string_view pov_classic_models_text();
/// The cushions, the wooden rail and its diamond sights, which both looks share.
std::string_view pov_cushions_and_rails_text();

}  // namespace bsim
