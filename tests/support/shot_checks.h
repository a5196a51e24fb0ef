#pragma once
// Physical sanity of a simulated shot, checked exactly: at every event and over every stretch between
// consecutive breakpoints (events and state transitions), where each ball's path is one quadratic.
// Used by the soak mode of the bench and by the property tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "detect.h"
#include "energy.h"
#include "motion.h"
#include "roots.h"
#include "scene.h"
#include "table.h"
#include "timeline.h"

namespace bsim::checks {

struct Faults {
  long overlaps = 0;      ///< two balls closer than 2R at an event
  long escapes = 0;       ///< a ball on the bed past a cushion's nose, at an event or between events
  long nans = 0;          ///< a non-finite number in a state
  long missed = 0;        ///< two balls overlapping between events: a contact the simulation missed
  long energy_gains = 0;  ///< a collision that created kinetic energy
  double deepest = 0;     ///< m, the largest overlap of two balls or of a ball and a cushion seen
  long total() const { return overlaps + escapes + nans + missed + energy_gains; }
};

/// m, overlap or cushion penetration counted as a fault: beyond what pushes may reach (detect.h); in a
/// cluster, separating one pair may press one of them a little further into a third ball.
inline constexpr double kFaultTolerance = 2 * kMaxPushOverlap;

namespace detail {

inline bool finite(const BallState& s) {
  return s.position.allFinite() && s.velocity.allFinite() && s.spin.allFinite() && s.orientation.coeffs().allFinite();
}

/// The ball's state at t from its segments, without orientation (cheap).
inline BallState state_at(const Timeline& timeline, int ball, double t) {
  const auto& list = timeline.segments(ball);
  auto it = std::upper_bound(list.begin(), list.end(), t, [](double v, const MotionSegment& s) { return v < s.t0; });
  if (it != list.begin()) --it;
  if (!on_bed(it->start)) return it->start;
  const double dt = std::min(t - it->t0, transition_time(it->start, timeline.physics()));
  return evolve(it->start, timeline.physics(), dt);
}

/// Smallest value of f on [0, length].
inline double minimum(const Poly& f, double length) {
  double low = std::min(f(0), f(length));
  const Roots crit = roots_in(f.derivative(), 0, length);
  for (int k = 0; k < crit.count; ++k) low = std::min(low, f(crit.t[static_cast<std::size_t>(k)]));
  return low;
}

inline Poly distance_poly(const Vec3& c, const Vec3& b, const Vec3& a, double d) {
  auto dot2 = [](const Vec3& u, const Vec3& v) { return u.x() * v.x() + u.y() * v.y(); };
  return Poly{{dot2(c, c) - d * d, 2 * dot2(b, c), dot2(b, b) + 2 * dot2(a, c), 2 * dot2(a, b), dot2(a, a)}};
}

/// The breakpoints of the shot: every segment's start within the shot and every event, sorted. A
/// non-finite segment start counts as a NaN.
inline std::vector<double> breakpoints(const Timeline& timeline, Faults& faults) {
  std::vector<double> times;
  for (int i = 0; i < timeline.ball_count(); ++i)
    for (const MotionSegment& seg : timeline.segments(i)) {
      if (!finite(seg.start) || !std::isfinite(seg.t0)) ++faults.nans;
      if (seg.t0 <= timeline.duration()) times.push_back(seg.t0);
    }
  for (const Event& e : timeline.events()) times.push_back(e.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

/// At each event: no NaN, no energy created by a collision, no two balls on the bed overlapping.
inline void check_events(const Timeline& timeline, Faults& faults) {
  const PhysicsParams& params = timeline.physics();
  const double R = params.ball_radius;
  const int n = timeline.ball_count();
  for (const Event& e : timeline.events()) {
    for (const auto* list : {&e.before, &e.after})
      for (const BallState& s : *list)
        if (!finite(s)) ++faults.nans;
    if (e.type == EventType::ball_ball || e.type == EventType::ball_rail || e.type == EventType::ball_jaw) {
      double before = 0, after = 0;
      for (const BallState& s : e.before) before += kinetic_energy(s, params);
      for (const BallState& s : e.after) after += kinetic_energy(s, params);
      if (after > before * (1 + 1e-12) + 1e-15) ++faults.energy_gains;
    }
    std::vector<BallState> states;
    for (int i = 0; i < n; ++i) states.push_back(state_at(timeline, i, e.time));
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const BallState &a = states[static_cast<std::size_t>(i)], &b = states[static_cast<std::size_t>(j)];
        if (!on_bed(a) || !on_bed(b)) continue;
        const double d = std::hypot(a.position.x() - b.position.x(), a.position.y() - b.position.y());
        faults.deepest = std::max(faults.deepest, 2 * R - d);
        if (d < 2 * R - kFaultTolerance) ++faults.overlaps;
      }
  }
}

/// What a ball on the bed must stay clear of, as the physics has it: each rail's nose line (ending, at a
/// cut pocket's jaw, where the jaw point's rounding begins), the facings of the cut pockets' jaws, and
/// the points: the rails' square ends and the jaws' roundings.
struct Cushions {
  struct Line {
    Rail rail;  ///< playing side on the right of a -> b
    double reach = 0;
  };
  struct Point {
    Vec3 at{0, 0, 0};
    double reach = 0;  ///< m from `at` the ball's centre stays
  };
  std::vector<Line> lines;
  std::vector<Point> points;
};

inline Cushions cushions_of(const Scene& scene) {
  Cushions c;
  const double R = scene.physics.ball_radius;
  for (const Rail& r : scene.rails) c.lines.push_back({r, cushion_reach(R, r.a.z())});
  std::vector<std::array<bool, 2>> jaw_end(scene.rails.size(), {false, false});
  for (const Pocket& pocket : scene.pockets) {
    const PocketMouth m = pocket_mouth(pocket, scene.rails);
    if (!m.cut) continue;
    for (int i = 0; i < 2; ++i) {
      const auto r = static_cast<std::size_t>(m.rail[i]);
      const double h = scene.rails[r].a.z(), reach = c.lines[r].reach;
      c.lines.push_back({m.facing_line(i, h), reach});
      c.points.push_back({m.round_centre[i], reach + m.round_radius});
      (m.at_b[i] ? c.lines[r].rail.b : c.lines[r].rail.a) = Vec3(m.nose_end[i].x(), m.nose_end[i].y(), h);
      jaw_end[r][m.at_b[i] ? 1 : 0] = true;
    }
  }
  for (std::size_t r = 0; r < scene.rails.size(); ++r)
    for (int e = 0; e < 2; ++e)
      if (!jaw_end[r][static_cast<std::size_t>(e)])
        c.points.push_back({e ? scene.rails[r].b : scene.rails[r].a, c.lines[r].reach});
  return c;
}

/// A ball moving along `p` for `length` seconds stays behind every cushion's nose (`reach` m from
/// each line) and clear of the points.
inline void check_rails(const Cushions& cushions, const Path& p, double length, Faults& faults) {
  const double tol = kFaultTolerance;
  for (const Cushions::Line& line : cushions.lines) {
    const Rail& rail = line.rail;
    const double reach = line.reach;
    const Vec3 along(rail.b.x() - rail.a.x(), rail.b.y() - rail.a.y(), 0);
    const double len = along.norm();
    const Vec3 dir = along / len, inward(dir.y(), -dir.x(), 0);
    const Vec3 rel(p.p.x() - rail.a.x(), p.p.y() - rail.a.y(), 0);
    const Poly s{{inward.dot(rel) - reach, inward.dot(p.v), 0.5 * inward.dot(p.a), 0, 0}};
    if (s.c[0] < -reach) continue;  // behind this cushion (another part of the table)
    const Roots crit = roots_in(s.derivative(), 0, length);
    for (double tau : {0.0, length, crit.count ? crit.t[0] : 0.0}) {
      const Vec3 at = p.at(tau);
      const double u = dir.dot(Vec3(at.x() - rail.a.x(), at.y() - rail.a.y(), 0));
      if (u >= 0 && u <= len) faults.deepest = std::max(faults.deepest, -s(tau));
      if (u >= 0 && u <= len && s(tau) < -tol) {
        ++faults.escapes;
        break;
      }
    }
  }
  for (const Cushions::Point& point : cushions.points) {
    const Poly g = distance_poly(p.p - point.at, p.v, 0.5 * p.a, point.reach);
    const double low = minimum(g, length);
    faults.deepest = std::max(faults.deepest, point.reach - std::sqrt(std::max(0.0, low + point.reach * point.reach)));
    if (low < -2 * point.reach * tol) ++faults.escapes;
  }
}

/// Over the stretch from `t` to `t + length`, where each ball's path is one quadratic: no two balls
/// on the bed pass through each other, and no moving ball passes a cushion.
inline void check_stretch(const Cushions& cushions, const Timeline& timeline, double t, double length, Faults& faults) {
  const PhysicsParams& params = timeline.physics();
  const double R = params.ball_radius;
  const int n = timeline.ball_count();
  std::vector<Path> paths;
  std::vector<bool> live;
  for (int i = 0; i < n; ++i) {
    const BallState s = state_at(timeline, i, t);
    live.push_back(on_bed(s));
    paths.push_back(path_of(s, params));
  }
  for (int i = 0; i < n; ++i) {
    if (!live[static_cast<std::size_t>(i)]) continue;
    const Path& p = paths[static_cast<std::size_t>(i)];
    const SweptBox box = swept_box(p, length);
    for (int j = i + 1; j < n; ++j) {
      const Path& q = paths[static_cast<std::size_t>(j)];
      if (!live[static_cast<std::size_t>(j)] || (!p.moves() && !q.moves())) continue;
      if (!boxes_within(box, swept_box(q, length), 2 * R)) continue;
      const Poly f = distance_poly(q.p - p.p, q.v - p.v, 0.5 * (q.a - p.a), 2 * R);
      const double low = minimum(f, length);
      faults.deepest = std::max(faults.deepest, 2 * R - std::sqrt(std::max(0.0, low + 4 * R * R)));
      if (low < -4 * R * kFaultTolerance) ++faults.missed;
    }
    if (p.moves()) check_rails(cushions, p, length, faults);
  }
}

}  // namespace detail

inline Faults find_faults(const Scene& scene, const Timeline& timeline) {
  using namespace detail;
  Faults faults;
  const std::vector<double> times = breakpoints(timeline, faults);
  check_events(timeline, faults);
  const Cushions cushions = cushions_of(scene);
  for (std::size_t k = 0; k + 1 < times.size(); ++k)
    check_stretch(cushions, timeline, times[k], times[k + 1] - times[k], faults);
  return faults;
}

}  // namespace bsim::checks
