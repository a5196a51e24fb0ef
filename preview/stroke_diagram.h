#pragma once
// The stroke as a small diagram: the struck ball as the shooter sees it, a dot where the tip meets it,
// the 0.5 R miscue limit as a faint ring, and the stroke's speed and elevation beside it. The timeline
// picture draws it at the right end of its title, the window in a small panel.
#include <imgui.h>

#include "fonts.h"
#include "scene.h"

namespace bsim {

/// Where the tip meets the ball in a drawing of it centred at `centre` with `radius` px (y down): the
/// stroke's side to the right and its height up, both fractions of the radius.
ImVec2 stroke_tip_point(const Stroke& stroke, ImVec2 centre, float radius);

/// px the diagram takes with these fonts (text on the left, the ball on the right).
ImVec2 stroke_diagram_size(const UiFonts& fonts);

/// Where the ball's centre is in a diagram whose top left corner is `at`, and its radius in px.
struct StrokeDiagramBall {
  ImVec2 centre;
  float radius = 0;
};
StrokeDiagramBall stroke_diagram_ball(const UiFonts& fonts, ImVec2 at);

/// Draws the ball alone (no text): the ball centred at `centre` with `radius` px, the miscue ring and
/// the tip's dot; for a place too narrow for the whole diagram.
void draw_stroke_ball(ImDrawList& list, const Stroke& stroke, ImVec2 centre, float radius);

/// Draws the diagram with its top left corner at `at`.
void draw_stroke_diagram(ImDrawList& list, const Stroke& stroke, const UiFonts& fonts, ImVec2 at);

}  // namespace bsim
