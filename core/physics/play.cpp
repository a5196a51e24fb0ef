#include "play.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "aim.h"
#include "number_format.h"
#include "simulate.h"
#include "strike.h"
#include "table_escape.h"

namespace bsim {

namespace {

/// m, the step along the long axis between places tried for a ball put back.
constexpr double kRespotStep = 0.001;

/// The first ball on the bed but `self` that a ball centred at p would overlap, or -1.
int touching(const std::vector<Ball>& balls, const Vec3& p, int self, double radius) {
  for (std::size_t j = 0; j < balls.size(); ++j) {
    if (static_cast<int>(j) == self || balls[j].pocket >= 0) continue;
    if (std::hypot(balls[j].position.x() - p.x(), balls[j].position.y() - p.y()) < 2 * radius - 1e-9)
      return static_cast<int>(j);
  }
  return -1;
}

/// The centre's distance from the segment a-b on the bed, m.
double off_line(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = flat(b - a), ap = flat(p - a);
  const double t = ab.squaredNorm() > 0 ? std::clamp(ap.dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (ap - t * ab).norm();
}

/// "the cue ball", "the 7": a ball by its painted number.
std::string painted(const Ball& ball) {
  return ball.number == 0 ? "the cue ball" : "the " + std::to_string(ball.number);
}

/// Where the balls stood before shot `k` (from 0) that a failed `pot` is about, a line each, for a
/// message: the struck ball, the ball to pot and any ball near the lines from one to the other and on
/// to the pocket; the rest counted; then the balls down, a line per pocket.
std::string where_balls_were(const Scene& shot, const Cue& cue, int k) {
  const double reach = 4 * shot.physics.ball_radius;  // a ball this near a line may be in the way
  const Vec3& struck = shot.ball(cue.target).position;
  const Vec3& target = shot.ball(cue.pot_ball).position;
  const Vec3& pocket = shot.pockets[static_cast<std::size_t>(cue.pot_pocket)].center;
  std::string near;
  std::vector<std::string> down(shot.pockets.size());
  int elsewhere = 0;
  for (int i = 0; i < static_cast<int>(shot.balls.size()); ++i) {
    const Ball& ball = shot.ball(i);
    if (ball.pocket >= 0) {
      std::string& in = down[static_cast<std::size_t>(ball.pocket)];
      in += (in.empty() ? "" : ", ") + painted(ball);
    } else if (i == cue.target || i == cue.pot_ball || off_line(ball.position, struck, target) < reach ||
               off_line(ball.position, target, pocket) < reach) {
      near += "\n    " + ball_name(shot, i) + " at " + plan_text(ball.position);
    } else {
      ++elsewhere;
    }
  }
  std::string out = "\n  after shot " + std::to_string(k) + " the balls stood:" + near;
  if (elsewhere > 0)
    out += "\n    and " + std::to_string(elsewhere) + (elsewhere == 1 ? " other" : " others") +
           " on the bed, away from the shot's paths";
  std::string pockets;
  for (std::size_t p = 0; p < down.size(); ++p)
    if (!down[p].empty()) pockets += "\n    in " + pocket_name(shot.pockets, static_cast<int>(p)) + ": " + down[p];
  return out + (pockets.empty() ? "" : "\n  down:" + pockets);
}

/// The shot's `place` lines: each ball at rest where the line says, or where it first stood. A failure
/// when a placed ball lands on another.
std::optional<PlayFailure> place_balls(const Scene& scene, int k, Scene& shot, std::vector<char>& moved) {
  const Cue& cue = scene.cues[static_cast<std::size_t>(k)];
  const double radius = scene.physics.ball_radius;
  for (const BallPlacement& p : cue.places) {
    Ball& ball = shot.balls[static_cast<std::size_t>(p.ball)];
    const Vec3 at = p.at ? *p.at : scene.ball(p.ball).position;
    ball.position = Vec3(at.x(), at.y(), radius);
    ball.pocket = -1;
    moved[static_cast<std::size_t>(p.ball)] = 1;
  }
  for (const BallPlacement& p : cue.places) {
    const Vec3& at = shot.ball(p.ball).position;
    const int j = touching(shot.balls, at, p.ball, radius);
    if (j < 0) continue;
    return PlayFailure{k, p.loc,
                       "shot " + std::to_string(k + 1) + " places " + ball_name(scene, p.ball) + " at " +
                           plan_text(at) + " on " + ball_name(scene, j) + ", which stands at " +
                           plan_text(shot.ball(j).position) + "; place it at least " + format_number(2 * radius) +
                           " m (a ball's diameter) away, or place that ball too"};
  }
  return std::nullopt;
}

}  // namespace

Vec3 respot_place(const Scene& scene, const std::vector<Ball>& balls, int ball) {
  return spot_place(scene, balls, ball, kHeadSpotX, -1);
}

Vec3 spot_place(const Scene& scene, const std::vector<Ball>& balls, int ball, double x, int first) {
  const double radius = scene.physics.ball_radius;
  double lowest = x, highest = x;  // the cushions' reach along the long axis
  for (const Rail& r : scene.rails) {
    lowest = std::min({lowest, r.a.x(), r.b.x()});
    highest = std::max({highest, r.a.x(), r.b.x()});
  }
  for (int direction : {first, -first}) {
    for (int step = 0;; ++step) {
      const Vec3 p(x + direction * step * kRespotStep, kHeadSpotY, radius);
      if (p.x() - radius < lowest || p.x() + radius > highest) break;
      if (touching(balls, p, ball, radius) < 0) return p;
    }
  }
  return Vec3(x, kHeadSpotY, radius);  // a table packed full: the spot itself
}

ShotChain::ShotChain(const Scene& scene) : table_(scene), segments_(scene.balls.size()) {
  table_.cues.clear();
  table_.camera.clear();
  found_.struck = scene.balls;
}

std::vector<Ball> ShotChain::standing() const {
  std::vector<Ball> balls = table_.balls;
  if (shots_.empty()) return balls;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const MotionSegment& last = segments_[i].back();
    Ball& ball = balls[i];
    ball.position = last.start.position;
    ball.velocity.setZero();
    ball.spin.setZero();
    ball.pocket = last.start.motion == Motion::pocketed ? last.pocket : -1;
  }
  return balls;
}

void ShotChain::add(SimulationResult r, const std::vector<char>& moved, double offset, int k) {
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    auto& list = r.segments[i];
    const std::size_t first = k == 0 || moved[i] ? 0 : 1;
    for (std::size_t j = first; j < list.size(); ++j) {
      MotionSegment seg = list[j];
      seg.t0 += offset;
      segments_[i].push_back(seg);
    }
  }
  for (Event& e : r.events) {
    if (e.type == EventType::end || (k > 0 && e.type == EventType::start)) continue;
    e.time += offset;
    for (Contact& c : e.contacts) c.time += offset;
    e.shot = k;
    e.index = static_cast<int>(events_.size());
    events_.push_back(std::move(e));
  }
  for (PocketDrop d : r.drops) {
    d.time += offset;
    drops_.push_back(d);
  }
  shots_.push_back({offset, offset + kCueLeadTime, offset + r.rest});
}

Timeline ShotChain::finish() const {
  std::vector<Event> events = events_;
  Event end;
  end.type = EventType::end;
  end.time = shot_end(shots_.empty() ? 0.0 : shots_.back().rest);
  end.shot = std::max(0, shots() - 1);
  events.push_back(end);
  for (std::size_t i = 0; i < events.size(); ++i) events[i].index = static_cast<int>(i);
  return Timeline(table_, segments_, std::move(events), drops_, shots_);
}

namespace {

/// Why shot k's `pot` finds no heading, in words, with where the balls stood.
std::string no_heading(const Scene& scene, const Scene& shot, int k, const Cue& cue) {
  const std::string shot_name = "shot " + std::to_string(k + 1);
  const Ball& target = shot.ball(cue.pot_ball);
  if (target.pocket >= 0)
    return shot_name + " cannot pot " + ball_name(scene, cue.pot_ball) + ": it is already down, in " +
           pocket_name(scene.pockets, target.pocket) + where_balls_were(shot, cue, k);
  return (k == 0 ? "" : shot_name + ": ") + aim_cue(shot).failure + (k > 0 ? where_balls_were(shot, cue, k) : "");
}

}  // namespace

std::optional<PlayFailure> ShotChain::play(const Scene& scene, int k) {
  BSIM_EXPECT(k == shots() && k < scene.shot_count(), "shots are played in order");
  const Cue& cue = scene.cues[static_cast<std::size_t>(k)];
  Scene shot = table_;  // one shot's scene: its cue alone, the balls where they stand before it
  shot.cues = {cue};
  std::vector<char> moved(shot.balls.size(), 0);
  const double offset = k == 0 ? 0.0 : shots_.back().rest;
  if (k > 0) {
    shot.balls = standing();
    if (auto failure = place_balls(scene, k, shot, moved)) return failure;
    Ball& struck = shot.balls[static_cast<std::size_t>(cue.target)];
    if (struck.pocket >= 0) {  // a scratch: back on the head spot
      struck.pocket = -1;
      struck.position = respot_place(scene, shot.balls, cue.target);
      moved[static_cast<std::size_t>(cue.target)] = 1;
    }
  }
  if (cue.aims()) {
    const Ball& target = shot.ball(cue.pot_ball);
    const std::optional<double> heading = target.pocket >= 0 ? std::nullopt : aim_cue(shot).heading_deg;
    if (!heading) return PlayFailure{k, cue.loc, no_heading(scene, shot, k, cue)};
    const Scene written = shot;
    strike_heading(written, *heading, shot);
  } else {
    strike_cue_ball(shot);
  }
  found_.headings.push_back(shot.cue().heading_deg);
  if (k == 0) found_.struck = shot.balls;  // the first shot's struck ball as struck
  SimulationResult simulated = simulate_events(shot);
  // The guard: a ball off the bed fails the run (the shot is still laid down, for a picture of it).
  const std::optional<TableEscape> escape = first_escape(shot, simulated);
  add(std::move(simulated), moved, offset, k);
  if (escape) return PlayFailure{k, cue.loc, escape_message(shot, *escape, offset)};
  return std::nullopt;
}

PlayResult play(const Scene& scene) {
  ShotChain chain(scene);
  PlayResult result;
  for (int k = 0; k < scene.shot_count() && !result.failure; ++k) result.failure = chain.play(scene, k);
  result.timeline = chain.finish();
  result.found = chain.found();
  return result;
}

void write_found(Scene& scene, const PlayFound& found) {
  for (std::size_t k = 0; k < found.headings.size() && k < scene.cues.size(); ++k)
    scene.cues[k].heading_deg = found.headings[k];
  if (found.struck.size() == scene.balls.size()) scene.balls = found.struck;
}

Timeline simulate(const Scene& scene) {
  Scene played = scene;
  for (Cue& cue : played.cues) cue.pot_ball = -1;  // the headings as given
  return play(played).timeline;
}

}  // namespace bsim
