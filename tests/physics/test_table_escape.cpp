// The physics' guard (table_escape.h): a ball that leaves the bed other than into a pocket fails the
// run, naming the ball, the time and the place. Scenes built in code, which skip the scene check.
#include <doctest/doctest.h>

#include "play.h"
#include "random_scenes.h"
#include "simulate.h"
#include "table_escape.h"

using namespace bsim;

namespace {

Ball ball(int number, double x, double y, double vx = 0, double vy = 0) {
  return scenes::ball_at(number, x, y, PhysicsParams{}, Vec3(vx, vy, 0));
}

/// The standard cushions without pockets: six open gaps.
Scene open_table(std::vector<Ball> balls) {
  Scene scene;
  scene.rails = standard_rails();
  scene.balls = std::move(balls);
  return scene;
}

}  // namespace

TEST_SUITE("the table's guard") {
  TEST_CASE("a ball through a gap no pocket fills is caught where it crosses the cushions' box") {
    // The 3 sent straight up through the top side gap (no pocket there).
    Scene scene = open_table({ball(0, -0.5, -0.3), ball(3, 0, 0, 0, 2)});
    const SimulationResult result = simulate_events(scene);
    const std::optional<TableEscape> escape = first_escape(scene, result);
    REQUIRE(escape);
    CHECK(escape->ball == 1);
    CHECK(escape->where.y() == doctest::Approx(0.635 + kEscapeTolerance).epsilon(1e-9));
    CHECK(escape->where.x() == doctest::Approx(0).scale(1).epsilon(1e-9));
    CHECK(escape->time > kCueLeadTime);
    CHECK(escape->time < kCueLeadTime + 0.635 / 1.5);  // well before it could have slowed to 1.5 m/s
    const PlayResult played = play(scene);
    REQUIRE(played.failure);
    CHECK(played.failure->message.find("the 3 (ball index 1) left the table at 2.8") == 0);
    CHECK(played.failure->message.find(", at (0.000, 0.636), without dropping into a pocket") != std::string::npos);
    // The shot is still in the timeline (for a picture of it).
    CHECK(played.timeline.shot_count() == 1);
  }

  TEST_CASE("the same shot on the standard table: the ball drops into the side pocket, nothing is caught") {
    Scene scene = scenes::standard_table();
    scene.balls = {ball(0, -0.5, -0.3), ball(3, 0, 0, 0, 2)};
    const SimulationResult result = simulate_events(scene);
    CHECK_FALSE(first_escape(scene, result));
    REQUIRE(result.drops.size() == 1);
    CHECK_FALSE(play(scene).failure);
  }

  TEST_CASE("a ball standing off the bed is caught at once") {
    Scene scene = scenes::standard_table();
    scene.balls = {ball(0, -0.5, 0, 1, 0), ball(5, -1.6, 0)};
    const std::optional<TableEscape> escape = first_escape(scene, simulate_events(scene));
    REQUIRE(escape);
    CHECK(escape->ball == 1);
    CHECK(escape->time == 0);
  }

  TEST_CASE("a table with no cushions has no edge to leave") {
    Scene scene;
    scene.balls = {ball(0, 0, 0, 1, 0)};
    CHECK_FALSE(first_escape(scene, simulate_events(scene)));
  }

  TEST_CASE("a ball rolling off along a diagonal is caught on the first side it crosses") {
    // Out through the top-left corner gap, at 45 degrees, nearer the top side.
    Scene scene = open_table({ball(0, -1.0, 0.4, -3, 3)});
    const std::optional<TableEscape> escape = first_escape(scene, simulate_events(scene));
    REQUIRE(escape);
    CHECK(escape->where.y() == doctest::Approx(0.636));
    CHECK(escape->where.x() > -1.27);
  }
}
