// The stroke's ball diagram: where the tip's dot goes (side to the right, height up, as README's "The
// stroke" defines them, in fractions of the radius), and that the timeline picture of a stroke scene
// draws it at the right end of its title while a scene without a stroke has none.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <imgui.h>

#include "files.h"
#include "headless_canvas.h"
#include "shot.h"
#include "stroke_diagram.h"
#include "support.h"
#include "timeline_picture.h"

using namespace bsim;

namespace {

struct Rgb {
  int r, g, b;
};

struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // bottom row first
  StrokeDiagramBall ball;          ///< where the diagram's ball is, as timeline_picture.cpp places it
  Rgb at(ImVec2 p) const {
    const int x = static_cast<int>(p.x), y = height - 1 - static_cast<int>(p.y);
    const std::uint8_t* q = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    return {q[0], q[1], q[2]};
  }
};

Picture draw(const TimelineData& data, int width, int height) {
  HeadlessCanvas canvas;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(width, height, 16, error), error);
  ImDrawList* list = canvas.begin_2d();
  draw_timeline(*list, data, canvas.fonts(), {0, 0, float(width), float(height)});
  canvas.end_2d();
  // Where timeline_picture.cpp puts the diagram: its top right corner one spacing unit (0.6 of the
  // body text, rounded) in from the picture's top right corner.
  const UiFonts& fonts = canvas.fonts();
  const float pad = std::round(fonts.regular_size * 0.6f);
  const ImVec2 size = stroke_diagram_size(fonts);
  return {width, height, canvas.pixels(), stroke_diagram_ball(fonts, ImVec2(float(width) - pad - size.x, pad))};
}

// The tip's chalk blue of the dot, and the ivory of the ball around it.
bool is_tip_blue(Rgb c) { return c.b > 150 && c.r < 100 && c.b > c.g + 60; }
bool is_ivory(Rgb c) { return c.r > 200 && c.g > 200 && c.b > 190; }

}  // namespace

TEST_SUITE("preview stroke diagram") {
  TEST_CASE("the tip's dot: side to the right, height up, fractions of the drawn radius") {
    Stroke stroke;
    stroke.speed = 1.5;
    stroke.side = 0.3;
    stroke.height = -0.45;  // draw: below the centre, so lower in the picture (y grows downwards)
    const ImVec2 p = stroke_tip_point(stroke, ImVec2(100, 50), 20);
    CHECK(p.x == doctest::Approx(106));
    CHECK(p.y == doctest::Approx(59));
    stroke.side = -0.5;
    stroke.height = 0.5;  // follow with left english: up and to the left
    const ImVec2 q = stroke_tip_point(stroke, ImVec2(100, 50), 20);
    CHECK(q.x == doctest::Approx(90));
    CHECK(q.y == doctest::Approx(40));
  }

  TEST_CASE("the timeline picture of scenes/draw.scn shows the dot below the ball's centre; without a stroke, none") {
    // scenes/draw.scn: `stroke 2.8 0 -0.45 0`, a centre-line stroke 0.45 R below centre.
    const ShotResult loaded = load_shot(test::require_file(test::source_path("scenes/draw.scn")), "draw", {});
    REQUIRE(loaded.shot);
    const TimelineData with = timeline_data(*loaded.shot);
    REQUIRE(with.stroke);
    CHECK(with.stroke->height == doctest::Approx(-0.45));
    TimelineData without = with;
    without.stroke.reset();
    constexpr int kWidth = 1600, kHeight = 420;
    const Picture a = draw(with, kWidth, kHeight);
    const Picture b = draw(without, kWidth, kHeight);
    const StrokeDiagramBall& ball = a.ball;
    const ImVec2 tip = stroke_tip_point(*with.stroke, ball.centre, ball.radius);
    CHECK(tip.y > ball.centre.y + 0.4f * ball.radius);
    CHECK(is_tip_blue(a.at(tip)));
    CHECK_FALSE(is_tip_blue(b.at(tip)));
    CHECK_FALSE(is_ivory(b.at(tip)));
    // Above the centre, off the centre line and inside the miscue ring: the ball's ivory, no dot.
    const ImVec2 mirrored(ball.centre.x + 0.2f * ball.radius, ball.centre.y - 0.3f * ball.radius);
    CHECK(is_ivory(a.at(mirrored)));
    CHECK_FALSE(is_ivory(b.at(mirrored)));
  }
}
