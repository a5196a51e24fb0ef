#pragma once
// Physical sanity of a simulated shot, checked exactly: at every event and over every stretch between
// consecutive breakpoints (events and state transitions), where each ball's path is one quadratic.
// Used by the soak mode of the bench and by the property tests.
#include <algorithm>
#include <cmath>
#include <vector>

#include "detect.h"
#include "energy.h"
#include "motion.h"
#include "roots.h"
#include "scene.h"
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

inline bool on_bed(const BallState& s) { return s.motion != Motion::falling && s.motion != Motion::pocketed; }

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
    if (e.type == EventType::ball_ball || e.type == EventType::ball_rail) {
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

/// A ball moving along `p` for `length` seconds stays behind every cushion's nose (`reach` m from
/// each rail's line) and clear of the rails' ends.
inline void check_rails(const Scene& scene, const Path& p, double length, const std::vector<double>& reach,
                        Faults& faults) {
  const double tol = kFaultTolerance;
  for (std::size_t r = 0; r < scene.rails.size(); ++r) {
    const Rail& rail = scene.rails[r];
    const Vec3 along(rail.b.x() - rail.a.x(), rail.b.y() - rail.a.y(), 0);
    const double len = along.norm();
    const Vec3 dir = along / len, inward(dir.y(), -dir.x(), 0);
    const Vec3 rel(p.p.x() - rail.a.x(), p.p.y() - rail.a.y(), 0);
    const Poly s{{inward.dot(rel) - reach[r], inward.dot(p.v), 0.5 * inward.dot(p.a), 0, 0}};
    if (s.c[0] < -reach[r]) continue;  // behind this cushion (another part of the table)
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
    for (const Vec3* end : {&rail.a, &rail.b}) {
      const Poly g = distance_poly(p.p - *end, p.v, 0.5 * p.a, reach[r]);
      const double low = minimum(g, length);
      faults.deepest = std::max(faults.deepest, reach[r] - std::sqrt(std::max(0.0, low + reach[r] * reach[r])));
      if (low < -2 * reach[r] * tol) ++faults.escapes;
    }
  }
}

/// Over the stretch from `t` to `t + length`, where each ball's path is one quadratic: no two balls
/// on the bed pass through each other, and no moving ball passes a cushion.
inline void check_stretch(const Scene& scene, const Timeline& timeline, double t, double length,
                          const std::vector<double>& reach, Faults& faults) {
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
    if (p.moves()) check_rails(scene, p, length, reach, faults);
  }
}

}  // namespace detail

inline Faults find_faults(const Scene& scene, const Timeline& timeline) {
  using namespace detail;
  Faults faults;
  const std::vector<double> times = breakpoints(timeline, faults);
  check_events(timeline, faults);
  std::vector<double> reach;
  for (const Rail& r : scene.rails) reach.push_back(cushion_reach(timeline.physics().ball_radius, r.a.z()));
  for (std::size_t k = 0; k + 1 < times.size(); ++k)
    check_stretch(scene, timeline, times[k], times[k + 1] - times[k], reach, faults);
  return faults;
}

}  // namespace bsim::checks
