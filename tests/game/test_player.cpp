// The player (player.h): a straight pot planned into its pocket and made, the chance falling with the
// noise, the break from the kitchen into the apex ball, ball in hand on a free spot, a legal safety when
// every pot is blocked, the noise's spread and determinism. Every "made" and "legal" is read from the
// physics' own events (simulate_events), not from the player's estimate.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "player.h"
#include "random_scenes.h"
#include "simulate.h"

using namespace bsim;

namespace {

constexpr double kR = 0.028575;

/// The standard table with balls (painted number, x, y) in that file order.
Scene table_with(const std::vector<std::array<double, 3>>& balls) {
  Scene scene = scenes::standard_table();
  for (const auto& b : balls) scene.balls.push_back(scenes::ball_at(static_cast<int>(b[0]), b[1], b[2], scene.physics));
  return scene;
}

ShotRules nine_ball_rules(int lowest) {
  ShotRules rules;
  rules.targets = {lowest};
  rules.winning_ball = 9;
  return rules;
}

/// The plan played without noise from `table`: its place, heading and stroke.
SimulationResult replay(const Scene& table, const PlannedShot& plan, Scene* played = nullptr) {
  Scene scene = table;
  int cue = 0;
  for (std::size_t i = 0; i < scene.balls.size(); ++i)
    if (scene.balls[i].number == 0) cue = static_cast<int>(i);
  if (plan.place) scene.balls[static_cast<std::size_t>(cue)].position = *plan.place;
  Cue c;
  c.target = cue;
  c.heading_deg = plan.heading_deg;
  c.stroke = plan.stroke;
  scene.cues = {c};
  if (played) *played = scene;
  return simulate_events(scene);
}

/// The painted number of the first ball the cue ball (number 0) touches, or -1.
int first_hit(const Scene& scene, const SimulationResult& r) {
  for (const Event& e : r.events)
    for (const Contact& c : e.contacts) {
      if (scene.balls[static_cast<std::size_t>(c.a)].number == 0)
        return scene.balls[static_cast<std::size_t>(c.b)].number;
      if (scene.balls[static_cast<std::size_t>(c.b)].number == 0)
        return scene.balls[static_cast<std::size_t>(c.a)].number;
    }
  return -1;
}

bool made(const Scene& scene, const SimulationResult& r, int number, int pocket) {
  for (const PocketDrop& d : r.drops)
    if (scene.balls[static_cast<std::size_t>(d.ball)].number == number && d.pocket == pocket) return true;
  return false;
}

bool scratched(const Scene& scene, const SimulationResult& r) {
  for (const PocketDrop& d : r.drops)
    if (scene.balls[static_cast<std::size_t>(d.ball)].number == 0) return true;
  return false;
}

/// A ball met a cushion or a jaw after the cue ball's first contact.
bool cushion_after_contact(const Scene& scene, const SimulationResult& r) {
  double first = -1;
  for (const Event& e : r.events) {
    for (const Contact& c : e.contacts)
      if (first < 0 && (scene.balls[static_cast<std::size_t>(c.a)].number == 0 ||
                        scene.balls[static_cast<std::size_t>(c.b)].number == 0))
        first = c.time;
    if (first >= 0 && (e.type == EventType::ball_rail || e.type == EventType::ball_jaw) && e.time >= first) return true;
  }
  return false;
}

/// A 9-ball rack on the foot spot with the cue ball on the head spot.
Scene racked(RackGame game, std::uint64_t seed) {
  Scene scene = scenes::standard_table();
  scene.balls.push_back(scenes::ball_at(0, -0.635, 0, scene.physics));
  RackSpec spec;
  spec.game = game;
  spec.seed = seed;
  for (const RackedBall& b : rack_balls(spec))
    scene.balls.push_back(scenes::ball_at(b.number, b.x, b.y, scene.physics));
  return scene;
}

bool same_plan(const PlannedShot& a, const PlannedShot& b) {
  auto bits = [](double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
  };
  return bits(a.heading_deg) == bits(b.heading_deg) && bits(a.stroke.speed) == bits(b.stroke.speed) &&
         bits(a.stroke.side) == bits(b.stroke.side) && bits(a.stroke.height) == bits(b.stroke.height) &&
         bits(a.stroke.elevation_deg) == bits(b.stroke.elevation_deg) && a.place.has_value() == b.place.has_value() &&
         (!a.place || (*a.place - *b.place).norm() == 0) && a.call == b.call && bits(a.chance) == bits(b.chance) &&
         a.simulations == b.simulations;
}

}  // namespace

TEST_CASE("a straight-in pot is planned into its pocket and made without noise") {
  // The 1 half way between the cue ball and the top side pocket (pocket 1), straight in; the 9 far off.
  const Scene table = table_with({{0, 0.0, -0.25}, {1, 0.0, 0.2}, {9, -0.9, -0.4}});
  const PlannedShot plan = plan_shot(table, nine_ball_rules(1), {"A", 0.0}, 7);
  CHECK(plan.call.ball == 1);
  CHECK(plan.call.pocket == 1);
  CHECK_FALSE(plan.call.safety);
  CHECK(plan.chance == 1.0);
  CHECK(plan.simulations > 0);
  CHECK_FALSE(plan.place.has_value());
  Scene played;
  const SimulationResult r = replay(table, plan, &played);
  CHECK(made(played, r, 1, 1));
  CHECK_FALSE(scratched(played, r));
  CHECK(first_hit(played, r) == 1);
}

TEST_CASE("a hard cut's chance falls with the player's noise") {
  // A 54-degree cut of the 1 into the top-right corner (pocket 2), the only pocket it can go in.
  const Scene table = table_with({{0, 0.4, -0.2}, {1, 0.7, 0.5}, {9, -0.9, -0.4}});
  const PlannedShot sure = plan_shot(table, nine_ball_rules(1), {"A", 0.0}, 3);
  const PlannedShot shaky = plan_shot(table, nine_ball_rules(1), {"B", 5.0}, 3);
  CHECK(sure.call.ball == 1);
  CHECK(sure.call.pocket == 2);
  CHECK(sure.chance == 1.0);
  CHECK_FALSE(shaky.call.safety);
  CHECK(shaky.chance < sure.chance);
  Scene played;
  const SimulationResult r = replay(table, sure, &played);
  CHECK(made(played, r, 1, 2));
}

TEST_CASE("the break puts the cue ball in the kitchen and strikes the apex ball first, hard") {
  for (RackGame game : {RackGame::nine_ball, RackGame::eight_ball}) {
    const Scene table = racked(game, 11);
    ShotRules rules;
    rules.break_shot = true;
    rules.in_hand = InHand::kitchen;
    rules.winning_ball = game == RackGame::nine_ball ? 9 : 8;
    rules.targets = game == RackGame::nine_ball ? std::vector<int>{1}
                                                : std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
    const PlannedShot plan = plan_shot(table, rules, {"A", 1.0}, 5);
    REQUIRE(plan.place.has_value());
    CHECK(plan.place->x() <= -0.635);
    CHECK(std::abs(plan.place->y()) < kStandardTable.half_width - kR);
    CHECK(plan.call.ball == -1);
    CHECK(plan.stroke.speed > 5.0);
    // The apex: the 1 in 9-ball, the ball nearest the head string in 8-ball (the foot spot's).
    int apex = 1;
    double front = 1e9;
    for (const Ball& b : table.balls)
      if (b.number != 0 && b.position.x() < front) {
        front = b.position.x();
        if (game == RackGame::eight_ball) apex = b.number;
      }
    Scene played;
    const SimulationResult r = replay(table, plan, &played);
    CHECK(first_hit(played, r) == apex);
  }
}

TEST_CASE("ball in hand puts the cue ball on the bed, on no ball, and behind the head string in the kitchen") {
  // The 3 near the foot rail, other balls about; the cue ball (down after a scratch) in a pocket.
  Scene table = table_with({{0, -0.2, 0.0}, {3, 0.6, 0.2}, {4, 0.5, -0.3}, {5, -0.4, 0.3}, {9, 0.9, 0.4}});
  table.balls[0].pocket = 2;
  for (InHand where : {InHand::anywhere, InHand::kitchen}) {
    ShotRules rules = nine_ball_rules(3);
    rules.in_hand = where;
    const PlannedShot plan = plan_shot(table, rules, {"A", 1.0}, 9);
    REQUIRE(plan.place.has_value());
    const Vec3 p = *plan.place;
    CHECK(std::abs(p.x()) < kStandardTable.half_length - kR);
    CHECK(std::abs(p.y()) < kStandardTable.half_width - kR);
    CHECK(p.z() == doctest::Approx(kR));
    if (where == InHand::kitchen) CHECK(p.x() <= -0.635);
    for (std::size_t i = 1; i < table.balls.size(); ++i)
      CHECK(std::hypot(table.balls[i].position.x() - p.x(), table.balls[i].position.y() - p.y()) >= 2 * kR);
    if (where == InHand::anywhere) {
      CHECK(plan.call.ball == 3);
      Scene played;
      Scene down_cue = table;
      down_cue.balls[0].pocket = -1;
      const SimulationResult r = replay(down_cue, plan, &played);
      CHECK(first_hit(played, r) == 3);
    }
  }
}

/// The 1 at (0.3, 0) with a ball on its line to each of the six pockets 0.15 m out; the cue ball above
/// it, in the gap between the lines to the top side and the top-right corner; the 9 far off.
Scene blocked_table() {
  const double ox = 0.3, oy = 0.0;
  std::vector<std::array<double, 3>> balls = {{0, ox + 0.5 * std::cos(1.29), oy + 0.5 * std::sin(1.29)}, {1, ox, oy}};
  const Scene bare = scenes::standard_table();
  int number = 2;
  for (const Pocket& p : bare.pockets) {
    const Vec3 mouth = p.cut ? Vec3((p.jaw[0] + p.jaw[1]) / 2) : p.center;
    const double dx = mouth.x() - ox, dy = mouth.y() - oy, d = std::hypot(dx, dy);
    balls.push_back({static_cast<double>(number++), ox + 0.15 * dx / d, oy + 0.15 * dy / d});
  }
  balls.push_back({9, -0.9, -0.4});
  return table_with(balls);
}

TEST_CASE("with every pot blocked the player plays a legal safety") {
  const Scene table = blocked_table();
  const PlannedShot plan = plan_shot(table, nine_ball_rules(1), {"A", 1.0}, 4);
  CHECK(plan.call.safety);
  CHECK(plan.call.ball == -1);
  CHECK(plan.chance == 0.0);
  Scene played;
  const SimulationResult r = replay(table, plan, &played);
  // Legal: the 1 first, then a ball to a cushion or a ball made; the cue ball stays up.
  CHECK(first_hit(played, r) == 1);
  CHECK((cushion_after_contact(played, r) || !r.drops.empty()));
  CHECK_FALSE(scratched(played, r));
}

TEST_CASE("a push-out when every pot is blocked; a push-out is taken when a pot is likely") {
  ShotRules rules = nine_ball_rules(1);
  rules.may_push_out = true;
  const Scene blocked = blocked_table();
  const PlannedShot plan = plan_shot(blocked, rules, {"A", 1.0}, 4);
  CHECK(plan.call.push_out);
  CHECK_FALSE(plan.call.safety);
  Scene played;
  const SimulationResult r = replay(blocked, plan, &played);
  CHECK_FALSE(scratched(played, r));
  CHECK_FALSE(take_push_out(blocked, nine_ball_rules(1), {"B", 1.0}, 5));
  const Scene open = table_with({{0, 0.0, -0.25}, {1, 0.0, 0.2}, {9, -0.9, -0.4}});
  CHECK(take_push_out(open, nine_ball_rules(1), {"B", 1.0}, 5));
}

TEST_CASE("apply_noise: nothing at 0; at k the Olympiad's deviations times k, the same per seed") {
  Stroke planned;
  planned.speed = 2.0;
  planned.elevation_deg = 10;
  {
    SplitMix64 random(1);
    double heading = 33.0;
    Stroke s = planned;
    apply_noise(0, kR, random, heading, s);
    CHECK(heading == 33.0);
    CHECK(s.speed == planned.speed);
    CHECK(s.side == 0.0);
    CHECK(s.height == 0.0);
    CHECK(s.elevation_deg == planned.elevation_deg);
  }
  constexpr int kDraws = 2000;
  constexpr double k = 2.0;
  double sum[5] = {}, sum2[5] = {};
  SplitMix64 random(42), again(42);
  for (int n = 0; n < kDraws; ++n) {
    double heading = 33.0, heading2 = 33.0;
    Stroke s = planned, s2 = planned;
    apply_noise(k, kR, random, heading, s);
    apply_noise(k, kR, again, heading2, s2);
    REQUIRE(heading == heading2);
    REQUIRE(s.speed == s2.speed);
    REQUIRE(s.side == s2.side);
    const double d[5] = {heading - 33.0, s.elevation_deg - 10, s.side * kR, s.height * kR, s.speed - 2.0};
    for (int j = 0; j < 5; ++j) {
      sum[j] += d[j];
      sum2[j] += d[j] * d[j];
    }
  }
  const double want[5] = {k * kNoiseHeadingDeg, k * kNoiseElevationDeg, k * kNoiseOffsetM, k * kNoiseOffsetM,
                          k * kNoiseSpeed};
  for (int j = 0; j < 5; ++j) {
    const double mean = sum[j] / kDraws, sd = std::sqrt(sum2[j] / kDraws - mean * mean);
    INFO("parameter " << j << ": sd " << sd << " wanted " << want[j]);
    CHECK(std::abs(sd / want[j] - 1) < 0.1);
    CHECK(std::abs(mean) < 0.1 * want[j]);
  }
}

TEST_CASE("the same table, rules, skill and seed give the same plan to the bit") {
  const Scene table = table_with({{0, -0.3, -0.1}, {2, 0.5, 0.3}, {3, 0.8, -0.35}, {5, -0.6, 0.4}, {9, 0.2, 0.1}});
  const PlannedShot a = plan_shot(table, nine_ball_rules(2), {"A", 1.0}, 99);
  const PlannedShot b = plan_shot(table, nine_ball_rules(2), {"A", 1.0}, 99);
  CHECK(same_plan(a, b));
  CHECK(a.simulations > 0);
  CHECK(take_push_out(table, nine_ball_rules(2), {"A", 1.0}, 99) ==
        take_push_out(table, nine_ball_rules(2), {"A", 1.0}, 99));
}

TEST_CASE("position play: the pot leaves the cue ball an open line to the next ball, not one the 9 blocks") {
  // The 1 straight into the top side pocket; the 2 to the right on the 1's line, the 9 between them:
  // a stop shot leaves the 2 hidden behind the 9, so the player must draw or follow off that line.
  const Scene table = table_with({{0, 0.0, -0.25}, {1, 0.0, 0.2}, {2, 0.6, 0.14}, {9, 0.3, 0.14}});
  const PlannedShot plan = plan_shot(table, nine_ball_rules(1), {"A", 1.0}, 5);
  REQUIRE_FALSE(plan.call.safety);
  CHECK(plan.call.ball == 1);
  Scene played;
  const SimulationResult r = replay(table, plan, &played);
  REQUIRE(made(played, r, 1, plan.call.pocket));
  REQUIRE_FALSE(scratched(played, r));
  // Where each ball stops; the line from the cue ball to the 2 must pass the 9 by more than a ball.
  auto rest = [&](int number) {
    for (std::size_t i = 0; i < played.balls.size(); ++i)
      if (played.balls[i].number == number) return r.segments[i].back().start.position;
    return Vec3(0, 0, 0);
  };
  const Vec3 c = rest(0), two = rest(2), nine = rest(9);
  const Vec3 ab(two.x() - c.x(), two.y() - c.y(), 0), ap(nine.x() - c.x(), nine.y() - c.y(), 0);
  const double t = std::clamp(ap.dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  CHECK((ap - t * ab).norm() > 2 * kR);
  CHECK(ab.norm() < 1.2);  // near enough for an easy shot
}
