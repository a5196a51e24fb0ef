#include "stroke_diagram.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "labels.h"

namespace bsim {

namespace {

constexpr ImU32 kBall = IM_COL32(236, 234, 224, 255);  // the cue ball's ivory
constexpr ImU32 kEdge = IM_COL32(120, 124, 134, 255);  // its outline
constexpr ImU32 kCross = IM_COL32(0, 0, 0, 40);        // the centre lines
constexpr ImU32 kLimit = IM_COL32(200, 60, 50, 110);   // the miscue limit, faint
constexpr ImU32 kTip = IM_COL32(30, 90, 220, 255);     // the tip's chalk blue

float ball_radius(const UiFonts& fonts) { return std::round(fonts.regular_size * 1.7f); }

float text_column_width(const UiFonts& fonts) {
  // Wide enough for the longest speed ("15.00 m/s") and elevation ("89° up") text.
  return fonts.small->CalcTextSizeA(fonts.small_size, FLT_MAX, 0, "15.00 m/s").x;
}

float gap(const UiFonts& fonts) { return std::round(fonts.small_size * 0.6f); }

}  // namespace

ImVec2 stroke_tip_point(const Stroke& stroke, ImVec2 centre, float radius) {
  return ImVec2(centre.x + static_cast<float>(stroke.side) * radius,
                centre.y - static_cast<float>(stroke.height) * radius);
}

ImVec2 stroke_diagram_size(const UiFonts& fonts) {
  const float r = ball_radius(fonts);
  return ImVec2(text_column_width(fonts) + gap(fonts) + 2 * r + 2, 2 * r + 2);
}

StrokeDiagramBall stroke_diagram_ball(const UiFonts& fonts, ImVec2 at) {
  const float r = ball_radius(fonts);
  return {ImVec2(at.x + text_column_width(fonts) + gap(fonts) + r + 1, at.y + r + 1), r};
}

void draw_stroke_ball(ImDrawList& list, const Stroke& stroke, ImVec2 c, float r) {
  list.AddCircleFilled(c, r, kBall, 48);
  list.AddCircle(c, r, kEdge, 48, 1.f);
  list.AddLine(ImVec2(c.x - r, c.y), ImVec2(c.x + r, c.y), kCross);
  list.AddLine(ImVec2(c.x, c.y - r), ImVec2(c.x, c.y + r), kCross);
  list.AddCircle(c, static_cast<float>(Stroke::kMiscueOffset) * r, kLimit, 40, 1.f);
  // The tip's contact: a 13 mm tip's mark on a 57 mm ball, about 0.2 of the radius (at least 3 px).
  const float dot = std::max(3.f, r * 0.2f);
  list.AddCircleFilled(stroke_tip_point(stroke, c, r), dot, kTip, 20);
}

void draw_stroke_diagram(ImDrawList& list, const Stroke& stroke, const UiFonts& fonts, ImVec2 at) {
  const StrokeDiagramBall ball = stroke_diagram_ball(fonts, at);
  const ImVec2 c = ball.centre;
  const float r = ball.radius;
  draw_stroke_ball(list, stroke, c, r);
  char speed[32], elevation[32];
  std::snprintf(speed, sizeof speed, "%.2f m/s", stroke.speed);
  std::snprintf(elevation, sizeof elevation, "%.0f\xC2\xB0 up", stroke.elevation_deg);
  const float right = c.x - r - gap(fonts);
  const float line = fonts.small_size + 2;
  const float top = c.y - line;
  const float w1 = fonts.small->CalcTextSizeA(fonts.small_size, FLT_MAX, 0, speed).x;
  const float w2 = fonts.small->CalcTextSizeA(fonts.small_size, FLT_MAX, 0, elevation).x;
  list.AddText(fonts.small, fonts.small_size, ImVec2(right - w1, top), kLabelText, speed);
  list.AddText(fonts.small, fonts.small_size, ImVec2(right - w2, top + line), kLabelDim, elevation);
}

}  // namespace bsim
