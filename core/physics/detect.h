#pragma once
// When does a ball next touch another ball, a cushion or a pocket? Pure functions of the balls' paths
// (see motion.h): each returns the time from the paths' common start, or nullopt when nothing happens
// before `horizon`. Positions are quadratic in time, so a distance test is a polynomial of degree 4
// (ball-ball, cushion end, pocket) or 2 (cushion line), solved exactly by roots.h.
//
// Contacts already in place at t = 0 count only when the two close at more than kMinClosingSpeed.
// A touching pair that is not closing (a resting contact, one just resolved, or one ball pressing on
// another: the pusher's cloth friction drives it on) becomes a contact once it overlaps by
// kContactSlop, but no sooner than kPushInterval unless the overlap would pass kMaxPushOverlap first.
// So round-off never gives a false hit, a real one is never missed, and a sustained push is a train of
// gentle contacts (at most ~1 kHz, the overlap bounded) instead of an endless chatter.
#include <optional>

#include "motion.h"
#include "scene.h"

namespace bsim {

/// m, distance within which two surfaces count as touching (round-off of positions is ~1e-15 m).
inline constexpr double kTouchDistance = 1e-11;
/// m/s, closing speed above which touching surfaces collide at once. Slower, the contact waits as a
/// push does: this ends the geometric series of ever smaller contacts (a Zeno sequence) that pairwise
/// impulses make of a ball nudging another or of a cluster of three touching balls.
inline constexpr double kMinClosingSpeed = 1e-5;
/// m, overlap a touching, non-closing contact may reach before it is resolved as a collision.
inline constexpr double kContactSlop = 1e-10;
/// s, longest wait between two contacts of a pair that touches without closing (a push).
inline constexpr double kPushInterval = 1e-2;
/// m, largest overlap a push may reach within kPushInterval (far below a real ball's elastic compression).
inline constexpr double kMaxPushOverlap = 1e-6;

/// Axis-aligned box a path sweeps on [0, horizon].
struct SweptBox {
  Vec3 lo, hi;
};
SweptBox swept_box(const Path& path, double horizon);
/// Whether the two boxes come within `margin` of each other in the bed plane.
inline bool boxes_within(const SweptBox& a, const SweptBox& b, double margin) {
  return !(a.lo.x() > b.hi.x() + margin || b.lo.x() > a.hi.x() + margin || a.lo.y() > b.hi.y() + margin ||
           b.lo.y() > a.hi.y() + margin);
}

/// First contact of two balls whose centres must stay `distance` (2R) apart, in the bed plane.
std::optional<double> next_ball_ball(const Path& a, const Path& b, double distance, double horizon);

/// Horizontal distance between the ball's centre and a cushion's nose line at contact:
/// sqrt(R^2 - (h - R)^2) for a nose at height h (the nose touches the ball off its equator); the
/// scene's nose_reach (cushion_gaps.h), the one formula the scene's gap check also uses.
double cushion_reach(double ball_radius, double nose_height);

/// First contact of the ball with the nose line of `rail` between its end points (from the playing side).
std::optional<double> next_ball_cushion(const Path& ball, const Rail& rail, double reach, double horizon);

/// A nose line as next_ball_cushion meets it, worked out once for many balls: the rail, its unit direction
/// a -> b and its playing side's normal in the bed plane, and its length.
struct NoseLine {
  Rail rail;
  Vec3 dir{0, 0, 0};
  Vec3 inward{0, 0, 0};
  double length = 0;
};
NoseLine nose_line(const Rail& rail);
/// next_ball_cushion(ball, line.rail, reach, horizon), the same to the bit.
std::optional<double> next_ball_cushion(const Path& ball, const NoseLine& line, double reach, double horizon);

/// First contact of the ball with a cushion end point (a pocket jaw), from any side.
std::optional<double> next_ball_point(const Path& ball, const Vec3& point, double reach, double horizon);

/// First time the ball's centre enters the pocket's circle.
std::optional<double> next_pocket_entry(const Path& ball, const Pocket& pocket, double horizon);

}  // namespace bsim
