#include "scene_validate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "cushion_gaps.h"

namespace bsim {

namespace {

/// Numbers in messages: short, as a person would type them.
std::string fmt(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v == 0.0 ? 0.0 : v);
  return buffer;
}

std::string plural(std::size_t n, std::string_view word) {
  return std::to_string(n) + " " + std::string(word) + (n == 1 ? "" : "s");
}

std::string line_of(SourceLoc loc) { return loc.known() ? " (line " + std::to_string(loc.line) + ")" : ""; }

std::string rail_name(const Rail& rail, std::size_t index) {
  return "rail " + std::to_string(index) + (rail.loc.known() ? line_of(rail.loc) : " of the standard table");
}

/// z of the cross product of two directions in the table plane; > 0 when `v` is left of `u`.
double cross2(const Vec3& u, const Vec3& v) { return u.x() * v.y() - u.y() * v.x(); }

/// Distance in the table plane from `p` to the segment a-b (end points included).
double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Eigen::Vector2d pa(p.x() - a.x(), p.y() - a.y()), ab(b.x() - a.x(), b.y() - a.y());
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp(pa.dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (pa - t * ab).norm();
}

class Validator {
 public:
  Validator(const Scene& scene, const SceneSourceMap& map, std::vector<Diagnostic>& diagnostics)
      : scene_(scene), map_(map), diagnostics_(diagnostics), radius_(scene.physics.ball_radius) {}

  void run() {
    references();
    const std::size_t before = diagnostics_.size();
    for (std::size_t i = 0; i < scene_.rails.size(); ++i) rail(i);
    // With a rail the wrong way round, every ball near it would also look outside; one error is enough.
    rails_ok_ = diagnostics_.size() == before;
    for (std::size_t i = 0; i < scene_.balls.size(); ++i) ball_placement(i);
    if (scene_.cues.empty() && !scene_.game) return;  // a rack checked alone
    if (rails_ok_) cushion_gaps();
    if (scene_.cues.empty()) return;  // a game the players play from the break
    for (const Cue& cue : scene_.cues)
      if (cue.call_loc.known() && !scene_.game)
        error(cue.call_loc, "a call is judged by a game's rules, and this scene has no 'game' line");
    cue_heading();
    for (const Cue& cue : scene_.cues) later_shot(cue);
    if (scene_.game) game_cues();
  }

 private:
  void error(SourceLoc loc, std::string message) { diagnostics_.push_back({Severity::error, loc, std::move(message)}); }
  void warning(SourceLoc loc, std::string message) {
    diagnostics_.push_back({Severity::warning, loc, std::move(message)});
  }

  bool ball_exists(int index) const { return index >= 0 && static_cast<std::size_t>(index) < scene_.balls.size(); }

  std::string index_range() const {
    return "from 0 to " + std::to_string(scene_.balls.size() - 1) + " (the scene has " +
           plural(scene_.balls.size(), "ball") + ", numbered by their order in the file)";
  }

  /// Every reference to a ball by its file-order index.
  void references() {
    for (const Cue& cue : scene_.cues) {
      if (!ball_exists(cue.target))
        error(cue.target_loc,
              "expected a cue target ball index " + index_range() + ", found " + std::to_string(cue.target));
      else
        cue_ball_struck(cue);
      pot_references(cue);
    }
    for (const auto& spin : map_.spins)
      if (!ball_exists(spin.ball))
        error(spin.ball_loc,
              "expected a ball index for 'spin' " + index_range() + ", found " + std::to_string(spin.ball));
    // A game's shots are known once it is played: its camera keys are checked against the timeline.
    for (const CameraShot& shot : scene_.camera)
      if (!scene_.game && static_cast<std::size_t>(shot.key.shot + 1) > scene_.cues.size())
        error(shot.key.shot_loc, "expected a shot from 1 to " + std::to_string(scene_.cues.size()) +
                                     " (the scene has " + plural(scene_.cues.size(), "shot") +
                                     ", one per 'cue' line), found " + std::to_string(shot.key.shot + 1));
    for (const CameraShot& shot : scene_.camera)
      if (shot.mode != CameraMode::hover && !ball_exists(shot.ball))
        error(shot.ball_loc, std::string("expected the index of the ball the camera ") +
                                 (shot.mode == CameraMode::look ? "looks at " : "follows ") + index_range() +
                                 ", found " + std::to_string(shot.ball));
  }

  /// A `cue` line striking a numbered ball while the cue ball (painted 0) is elsewhere: most likely the
  /// index counts a `rack` line's balls or a `ball` line the writer forgot.
  void cue_ball_struck(const Cue& cue) {
    const Ball& struck = scene_.balls[static_cast<std::size_t>(cue.target)];
    if (struck.number == 0) return;
    const auto white =
        std::find_if(scene_.balls.begin(), scene_.balls.end(), [](const Ball& b) { return b.number == 0; });
    if (white == scene_.balls.end()) return;  // no cue ball: striking a numbered ball is the only way
    warning(cue.target_loc, "the cue strikes ball index " + std::to_string(cue.target) + ", the " +
                                std::to_string(struck.number) +
                                ", not the cue ball; the cue ball (painted 0) is ball index " +
                                std::to_string(white - scene_.balls.begin()) +
                                " (indices count the `ball` lines and a `rack` line's balls in file order)");
  }

  /// `cue I pot B P`: B and P must be there, B must not be the struck ball, and the struck ball needs a speed
  /// (its stroke's, or its `ball` line's).
  void pot_references(const Cue& cue) {
    if (!cue.aims()) return;
    if (!ball_exists(cue.pot_ball))
      error(cue.pot_ball_loc,
            "expected the index of the ball to pot " + index_range() + ", found " + std::to_string(cue.pot_ball));
    else if (cue.pot_ball == cue.target)
      error(cue.pot_ball_loc, "expected a ball to pot other than the struck one, found ball index " +
                                  std::to_string(cue.pot_ball) + ", the ball the cue strikes");
    if (static_cast<std::size_t>(cue.pot_pocket) >= scene_.pockets.size())
      error(cue.pot_pocket_loc, "expected a pocket number from 0 to " + std::to_string(scene_.pockets.size() - 1) +
                                    " (the table has " + plural(scene_.pockets.size(), "pocket") +
                                    (standard_pocket_set(scene_.pockets)
                                         ? ", numbered as in the README's standard table, or a pocket's name such "
                                           "as top-right), "
                                         : ", numbered by their order in the file), ") +
                                    "found " + std::to_string(cue.pot_pocket));
    if (ball_exists(cue.target) && !cue.stroke) {
      const Vec3& v = scene_.balls[static_cast<std::size_t>(cue.target)].velocity;
      if (std::hypot(v.x(), v.y()) == 0)
        error(cue.loc,
              "expected a speed to aim with: the struck ball's 'ball' line gives it no velocity along the "
              "table, and 'pot' turns that velocity to the heading it finds");
    }
  }

  /// In a game the stick strikes the cue ball, and every shot has its stroke (the rules judge a stroke).
  void game_cues() {
    for (const Cue& cue : scene_.cues) {
      if (!ball_exists(cue.target)) continue;
      if (scene_.ball(cue.target).number != 0)
        error(cue.target_loc, "in a game the stick strikes the cue ball, and ball index " + std::to_string(cue.target) +
                                  " is the " + std::to_string(scene_.ball(cue.target).number));
      else if (!cue.stroke && &cue == &scene_.cues.front())
        error(cue.loc, "expected a 'stroke' line under this cue: in a game every shot is struck by the stick");
      if (cue.call_ball >= 0 && !ball_exists(cue.call_ball))
        error(cue.call_loc,
              "expected the index of the called ball " + index_range() + ", found " + std::to_string(cue.call_ball));
      else if (cue.call_pocket >= static_cast<int>(scene_.pockets.size()))
        error(cue.call_loc, "expected the called pocket from 0 to " + std::to_string(scene_.pockets.size() - 1) +
                                ", found " + std::to_string(cue.call_pocket));
    }
  }

  /// A later shot is struck by its stroke from where the balls stopped; its `place` lines put balls on
  /// the bed.
  void later_shot(const Cue& cue) {
    if (&cue == &scene_.cues.front()) return;
    if (!cue.stroke)
      error(cue.loc,
            "expected a 'stroke' line under this cue: a later shot is struck by its stroke (the 'ball' "
            "lines' velocities are the first shot's)");
    for (const BallPlacement& p : cue.places) {
      if (!ball_exists(p.ball)) {
        error(p.ball_loc,
              "expected the index of the ball to place " + index_range() + ", found " + std::to_string(p.ball));
        continue;
      }
      if (!p.at) continue;
      Ball ball = scene_.balls[static_cast<std::size_t>(p.ball)];
      ball.position = Vec3(p.at->x(), p.at->y(), radius_);
      SceneSourceMap::BallTokens tokens{p.at_loc, p.at_loc, p.at_loc};
      if (!rails_ok_ || inside_cushions(ball, tokens)) over_pocket(ball, p.at_loc);
    }
  }

  void ball_placement(std::size_t i) {
    const Ball& ball = scene_.balls[i];
    const SceneSourceMap::BallTokens& tokens = map_.balls[i];
    const Vec3& p = ball.position;
    if (std::abs(p.z() - radius_) > kPlacementTolerance) {
      error(tokens.position_z, "expected the ball's centre on the bed at z = " + fmt(radius_) +
                                   " (the ball radius), found z = " + fmt(p.z()));
      return;  // the other placement checks would only repeat the problem
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double d = (scene_.balls[j].position - p).norm();
      if (d < 2 * radius_ - kPlacementTolerance)
        error(ball.loc, "ball " + std::to_string(ball.number) + " overlaps ball " +
                            std::to_string(scene_.balls[j].number) + line_of(scene_.balls[j].loc) +
                            ": expected their centres at least " + fmt(2 * radius_) +
                            " m apart (two ball radii), found " + fmt(d) + " m");
    }
    if (rails_ok_ && !inside_cushions(ball, tokens)) return;
    over_pocket(ball, tokens.position_x);
  }

  /// A warning at `loc` (where the ball's place is written) when the ball stands over a pocket: the
  /// same words for a `ball` line and a `place` line.
  void over_pocket(const Ball& ball, SourceLoc loc) {
    for (std::size_t k = 0; k < scene_.pockets.size(); ++k) {
      const Pocket& pocket = scene_.pockets[k];
      const Vec3 d = ball.position - pocket.center;
      if (std::hypot(d.x(), d.y()) < pocket.radius)
        warning(loc, "ball " + std::to_string(ball.number) + " starts over " +
                         pocket_name(scene_.pockets, static_cast<int>(k)) + line_of(pocket.loc) +
                         " and will drop into it");
    }
  }

  /// Whether the ball's centre stands in a cut pocket's opening, clear of its jaws: past the mouth line
  /// (on the shelf, or over the hole: over_pocket then warns), between the facings and their roundings.
  bool in_pocket_opening(const Vec3& p) const {
    for (const Pocket& pocket : scene_.pockets) {
      const PocketMouth m = pocket_mouth(pocket, scene_.rails);
      if (!m.cut) continue;
      const double reach = nose_reach(radius_, scene_.rails[static_cast<std::size_t>(m.rail[0])].a.z());
      const Vec3 q = flat(p);
      bool clear = (q - (m.nose[0] + m.nose[1]) / 2).dot(m.axis) > 0 && m.in_throat(q);
      for (int i = 0; clear && i < 2; ++i)
        clear = (q - m.face_start[i]).dot(m.inward[i]) >= reach - kPlacementTolerance &&
                (q - flat(m.round_centre[i])).norm() >= reach + m.round_radius - kPlacementTolerance;
      if (clear) return true;
    }
    return false;
  }

  /// Outside is: beyond the box the cushions span (a radius in from each side; exact for a
  /// rectangular table), behind the nearest cushion, or cutting into one. The nearest cushion decides
  /// because, on any table shape, the closest stretch of boundary tells which side a point is on.
  bool inside_cushions(const Ball& ball, const SceneSourceMap::BallTokens& tokens) {
    if (scene_.rails.empty()) return true;
    double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x, min_y = min_x, max_y = -min_x;
    for (const Rail& r : scene_.rails)
      for (const Vec3* e : {&r.a, &r.b}) {
        min_x = std::min(min_x, e->x());
        max_x = std::max(max_x, e->x());
        min_y = std::min(min_y, e->y());
        max_y = std::max(max_y, e->y());
      }
    const Vec3& p = ball.position;
    const double t = kPlacementTolerance;
    const double lo_x = min_x + radius_, hi_x = max_x - radius_, lo_y = min_y + radius_, hi_y = max_y - radius_;
    const bool encloses = lo_x < hi_x && lo_y < hi_y;  // a lone cushion or a wall spans no area
    if (in_pocket_opening(p)) return true;
    if (encloses && (p.x() < lo_x - t || p.x() > hi_x + t || p.y() < lo_y - t || p.y() > hi_y + t)) {
      error(tokens.position_x, "expected the ball inside the cushions (centre x from " + fmt(lo_x) + " to " +
                                   fmt(hi_x) + ", y from " + fmt(lo_y) + " to " + fmt(hi_y) +
                                   "), found x = " + fmt(p.x()) + ", y = " + fmt(p.y()));
      return false;
    }
    std::size_t nearest = 0;
    double nearest_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < scene_.rails.size(); ++k) {
      const double d = distance_to_segment(p, scene_.rails[k].a, scene_.rails[k].b);
      if (d < nearest_distance) {
        nearest_distance = d;
        nearest = k;
      }
    }
    const Rail& r = scene_.rails[nearest];
    const Vec3 along = r.b - r.a;
    const double length2 = along.x() * along.x() + along.y() * along.y();
    const double s = length2 > 0 ? (along.x() * (p.x() - r.a.x()) + along.y() * (p.y() - r.a.y())) / length2 : 0;
    if (s > 0 && s < 1 && cross2(along, p - r.a) > t * std::sqrt(length2)) {
      error(tokens.position_x, "expected the ball on the playing side of its nearest cushion, " +
                                   rail_name(r, nearest) + ", found it behind the cushion at x = " + fmt(p.x()) +
                                   ", y = " + fmt(p.y()));
      return false;
    }
    if (nearest_distance < radius_ - t) {
      error(tokens.position_x, "ball " + std::to_string(ball.number) + " cuts into the cushion of " +
                                   rail_name(r, nearest) + ": expected its centre at least " + fmt(radius_) +
                                   " m from the nose line, found " + fmt(nearest_distance) + " m");
      return false;
    }
    return true;
  }

  void rail(std::size_t index) {
    const Rail& r = scene_.rails[index];
    if (!r.loc.known()) return;  // the standard table's cushions are right by construction
    const SceneSourceMap::RailTokens& tokens = map_.rails[index];
    if (std::abs(r.a.z() - r.b.z()) > kPlacementTolerance)
      error(tokens.b_z, "expected the rail's second end at the same nose height as its first (z = " + fmt(r.a.z()) +
                            "), found z = " + fmt(r.b.z()));
    const Vec3 d = r.b - r.a;
    if (std::hypot(d.x(), d.y()) <= kPlacementTolerance) {
      error(r.loc, "expected a rail with two different end points, found both at x = " + fmt(r.a.x()) +
                       ", y = " + fmt(r.a.y()));
      return;
    }
    // The playing side is on the right of a->b. A rail whose right faces away from every ball (or,
    // with no balls, from the middle of the cushions) was listed anticlockwise.
    std::vector<Vec3> probes;
    for (const Ball& b : scene_.balls) probes.push_back(b.position);
    if (probes.empty()) {
      Vec3 sum(0, 0, 0);
      for (const Rail& other : scene_.rails) sum += other.a + other.b;
      probes.push_back(sum / (2.0 * static_cast<double>(scene_.rails.size())));
    }
    const bool faces_away = std::all_of(probes.begin(), probes.end(), [&](const Vec3& p) {
      return cross2(d, p - r.a) > kPlacementTolerance * d.norm();
    });
    if (faces_away)
      error(r.loc,
            "expected the rail's ends in clockwise order seen from above (the playing side is on the right "
            "walking from the first end to the second), found its playing side facing away from every ball; "
            "swap its two ends");
  }

  /// Where the table's outline lets a ball off the bed (cushion_gaps.h): an error at the line that
  /// makes that part of the table (the rail, else the first `pocket` line, else the first ball).
  void cushion_gaps() {
    bool enclosed = false;
    const std::vector<CushionGap> gaps = open_cushion_gaps(scene_.rails, scene_.pockets, radius_, enclosed);
    const bool own_rails = !scene_.rails.empty() && scene_.rails.front().loc.known();
    const bool own_pockets = !scene_.pockets.empty() && scene_.pockets.front().loc.known();
    auto blame = [&](int rail) {
      if (own_rails) return scene_.rails[static_cast<std::size_t>(rail)].loc;
      if (own_pockets) return scene_.pockets.front().loc;
      return scene_.balls.empty() ? map_.end : scene_.balls.front().loc;
    };
    if (!enclosed && !scene_.rails.empty())
      error(blame(0),
            "the cushions do not close round the bed: no run of `rail` lines goes round it clockwise, so a "
            "ball rolls off the table; give the table's edge as rails clockwise seen from above, with a "
            "`pocket` in each gap");
    const std::string replaced =
        own_pockets && !own_rails ? " (the scene's own `pocket` lines replace all six of the standard table's)" : "";
    for (const CushionGap& gap : gaps) {
      const Rail& from = scene_.rails[static_cast<std::size_t>(gap.from_rail)];
      if (gap.under) {
        error(blame(gap.from_rail), rail_name(from, static_cast<std::size_t>(gap.from_rail)) + " has its nose at z = " +
                                        fmt(from.a.z()) + ", so a ball (radius " + fmt(radius_) +
                                        ") rolls under it off the table; expected a nose above the bed and below "
                                        "the ball's diameter, " +
                                        fmt(2 * radius_) + " m");
        continue;
      }
      const Vec3 middle = (gap.a + gap.b) / 2;
      const double half = (gap.b - gap.a).norm() / 2;
      const std::string where =
          "from (" + fmt(gap.a.x()) + ", " + fmt(gap.a.y()) + ") to (" + fmt(gap.b.x()) + ", " + fmt(gap.b.y()) + ")";
      const std::string between = gap.from_rail == gap.to_rail
                                      ? "round the ends of " + rail_name(from, static_cast<std::size_t>(gap.from_rail))
                                      : "between rails " + std::to_string(gap.from_rail) + " and " +
                                            std::to_string(gap.to_rail) + (own_rails ? "" : " of the standard table");
      error(blame(gap.from_rail), "the gap " + between + ", " + where + ", has no pocket: a ball (radius " +
                                      fmt(radius_) + ") passes through it off the table" + replaced +
                                      "; add a `pocket` line there, such as `pocket " + fmt(middle.x()) + " " +
                                      fmt(middle.y()) + " 0 " + fmt(half) + "`");
    }
  }

  /// With a stroke the strike gives the struck ball its velocity and spin, so its lines give none.
  void cue_stroke() {
    const Stroke& stroke = *scene_.cue().stroke;
    const Ball& target = scene_.balls[static_cast<std::size_t>(scene_.cue().target)];
    if (target.velocity != Vec3(0, 0, 0))
      error(stroke.loc, "the stroke gives ball index " + std::to_string(scene_.cue().target) +
                            " its velocity, so expected velocity 0 0 0 on its ball line" + line_of(target.loc) +
                            ", found " + fmt(target.velocity.x()) + " " + fmt(target.velocity.y()) + " " +
                            fmt(target.velocity.z()));
    for (const auto& spin : map_.spins)
      if (spin.ball == scene_.cue().target)
        error(stroke.loc, "the stroke gives ball index " + std::to_string(scene_.cue().target) +
                              " its spin, so expected no 'spin' line for it, found one" + line_of(spin.loc));
  }

  void cue_heading() {
    if (!ball_exists(scene_.cue().target)) return;
    if (scene_.cue().stroke) return cue_stroke();
    if (scene_.cue().aims()) return;
    const Ball& target = scene_.balls[static_cast<std::size_t>(scene_.cue().target)];
    const double vx = target.velocity.x(), vy = target.velocity.y();
    const auto index = static_cast<std::size_t>(scene_.cue().target);
    if (index < map_.balls.size() && map_.balls[index].short_form) {
      const SceneSourceMap::BallTokens& tokens = map_.balls[index];
      // In the seed's form the struck ball's line gives the shot its velocity; a short line gives
      // none, and is most often a long line cut short.
      error(tokens.position_x, "the cue (line " + std::to_string(scene_.cue().target_loc.line) +
                                   ") strikes ball index " + std::to_string(scene_.cue().target) +
                                   ", whose short line 'ball N X Y' leaves it at rest, and there is no stroke; "
                                   "expected the whole line 'ball N X Y Z VX VY VZ W QX QY QZ' with the ball's "
                                   "velocity, or a 'stroke' line under the cue");
      return;
    }
    if (std::hypot(vx, vy) == 0) {
      warning(scene_.cue().target_loc, "the cue strikes ball index " + std::to_string(scene_.cue().target) +
                                           ", whose velocity has no part along the table; the stick will not move it");
      return;
    }
    const double along = std::atan2(vy, vx) * 180.0 / std::numbers::pi;
    double off = std::remainder(scene_.cue().heading_deg - along, 360.0);
    if (std::abs(off) > kHeadingToleranceDeg)
      warning(scene_.cue().heading_loc, "the cue's heading " + fmt(scene_.cue().heading_deg) +
                                            " degrees disagrees with its ball's velocity, which points at " +
                                            fmt(along) + " degrees (off by " + fmt(std::abs(off)) + " degrees)");
  }

  const Scene& scene_;
  const SceneSourceMap& map_;
  std::vector<Diagnostic>& diagnostics_;
  double radius_;
  bool rails_ok_ = true;
};

}  // namespace

void validate_scene(const Scene& scene, const SceneSourceMap& map, std::vector<Diagnostic>& diagnostics) {
  Validator(scene, map, diagnostics).run();
}

}  // namespace bsim
