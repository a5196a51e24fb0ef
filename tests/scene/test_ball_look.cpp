// One set of ball colours: the core's standard pool colours are what the GL preview shades and what
// the POV-Ray include declares.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "ball_look.h"
#include "ball_model.h"
#include "mesh.h"
#include "pov_format.h"
#include "pov_table.h"
#include "scene.h"

using namespace bsim;

namespace {

bool same(const SrgbColor& a, const SrgbColor& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

std::string pov_colour(const SrgbColor& c) {
  return "<" + pov_number(c.r / 255.0) + ", " + pov_number(c.g / 255.0) + ", " + pov_number(c.b / 255.0) + ">";
}

}  // namespace

TEST_SUITE("ball look") {
  TEST_CASE("the standard set: stripes share their solid's colour, the cue ball is ivory") {
    for (int n = 1; n <= 7; ++n) {
      CAPTURE(n);
      CHECK(same(ball_srgb(n + 8), ball_srgb(n)));
      CHECK_FALSE(ball_striped(n));
      CHECK(ball_striped(n + 8));
    }
    CHECK(same(ball_srgb(0), kBallIvory));
    CHECK_FALSE(ball_striped(8));
    CHECK(same(ball_srgb(16), kBallIvory));
    // 1 yellow, 3 red, 8 black: the channel that should lead does.
    CHECK(ball_srgb(1).r > ball_srgb(1).b);
    CHECK(ball_srgb(3).r > ball_srgb(3).g);
    CHECK(ball_srgb(8).r < 32);
  }

  TEST_CASE("the preview shades the core's colours") {
    for (int n = 0; n <= 15; ++n) {
      CAPTURE(n);
      const SrgbColor c = ball_srgb(n);
      CHECK((ball_color(n) - srgb(c.r, c.g, c.b)).norm() == 0);
    }
    CHECK((ball_ivory() - srgb(kBallIvory.r, kBallIvory.g, kBallIvory.b)).norm() == 0);
  }

  TEST_CASE("the POV-Ray include declares the core's colours, in number order") {
    Scene scene;
    scene.rails = standard_rails();
    scene.pockets = standard_pockets();
    std::ostringstream out;
    write_pov_include(scene, Quality::draft, out);
    const std::string text = out.str();
    const auto begin = text.find("#declare BallSrgb = array[16] {");
    REQUIRE(begin != std::string::npos);
    const std::string array = text.substr(begin, text.find('}', begin) - begin);
    std::size_t at = 0;
    for (int n = 0; n <= 15; ++n) {
      CAPTURE(n);
      const auto found = array.find(pov_colour(ball_srgb(n)), at);
      REQUIRE(found != std::string::npos);
      at = found + 1;
    }
    // The fixed models turn those numbers into colours and hold none of their own.
    const std::string models(pov_models_text());
    CHECK(models.find("#declare BallColour[N] = srgb BallSrgb[N];") != std::string::npos);
    CHECK(models.find("#declare BallWhite = srgb BallSrgb[0];") != std::string::npos);
    CHECK(models.find("srgb <0.98") == std::string::npos);
  }
}
