#include "detect.h"

#include <algorithm>
#include <cmath>

#include "cushion_gaps.h"
#include "roots.h"

namespace bsim {

namespace {

/// |c + b t + a t^2|^2 - d^2 in the bed plane, as a polynomial in t.
Poly circle_gap(const Vec3& c, const Vec3& b, const Vec3& a, double d) {
  auto dot2 = [](const Vec3& u, const Vec3& v) { return u.x() * v.x() + u.y() * v.y(); };
  return Poly{{dot2(c, c) - d * d, 2 * dot2(b, c), dot2(b, b) + 2 * dot2(a, c), 2 * dot2(a, b), dot2(a, a)}};
}

/// The first contact time given f, a measure of separation with f(0) = separation now: f > 0 apart,
/// and f = level(x) when the two overlap by x (level(0) = 0, decreasing). See detect.h for the rules.
template <class Level>
std::optional<double> first_contact(const Poly& f, double gap, double closing, double horizon, Level level) {
  if (gap > kTouchDistance) return first_descent(f, 0, horizon);
  if (closing > kMinClosingSpeed) return 0.0;
  const double overlap = std::max(0.0, -gap);
  auto overlap_reaches = [&](double x, double h) -> std::optional<double> {
    Poly g = f;
    g.c[0] -= level(x);
    return g.c[0] > 0 ? first_descent(g, 0, h) : std::optional<double>(0.0);
  };
  if (overlap >= kMaxPushOverlap) return overlap_reaches(overlap + kContactSlop, horizon);
  const std::optional<double> slop = overlap_reaches(overlap + kContactSlop, horizon);
  if (!slop || *slop >= kPushInterval) return slop;
  const std::optional<double> deep = overlap_reaches(kMaxPushOverlap, std::min(kPushInterval, horizon));
  if (deep) return deep;
  return kPushInterval <= horizon ? std::optional<double>(kPushInterval) : std::nullopt;
}

/// First time the relative motion c + b t + a t^2 (of a point about a centre) comes within d, in the plane.
std::optional<double> circle_contact(const Vec3& c, const Vec3& b, const Vec3& a, double d, double horizon) {
  // Cheap rejection: the box the relative motion sweeps stays farther than d from the centre.
  const SweptBox box = swept_box(Path{c, b, 2 * a}, horizon);
  for (int k = 0; k < 2; ++k)
    if (box.lo[k] > d || box.hi[k] < -d) return std::nullopt;
  const Poly f = circle_gap(c, b, a, d);
  const double distance = std::sqrt(f.c[0] + d * d);
  const double closing = distance > 0 ? -f.c[1] / (2 * distance) : 0.0;
  return first_contact(f, distance - d, closing, horizon, [d](double x) { return x * x - 2 * d * x; });
}

/// The top of s (a cushion's s(t) below), when s rises to it above the touching distance within the
/// horizon; else nullopt.
std::optional<double> rises_to_top(const Poly& s, double horizon) {
  if (s.c[2] >= 0) return std::nullopt;  // no top: once rising, s never comes back down
  const double top = -s.c[1] / (2 * s.c[2]);
  if (!(top > 0 && top < horizon) || s(top) <= kTouchDistance) return std::nullopt;
  return top;
}

void widen(SweptBox& box, const Vec3& p) {
  box.lo = box.lo.cwiseMin(p);
  box.hi = box.hi.cwiseMax(p);
}

}  // namespace

SweptBox swept_box(const Path& path, double horizon) {
  SweptBox box{path.p, path.p};
  if (!path.moves()) return box;
  widen(box, path.at(horizon));
  for (int k = 0; k < 3; ++k) {
    // Where this coordinate turns back, if it does within the horizon.
    if (path.a[k] == 0) continue;
    const double t = -path.v[k] / path.a[k];
    if (t > 0 && t < horizon) widen(box, path.at(t));
  }
  return box;
}

std::optional<double> next_ball_ball(const Path& a, const Path& b, double distance, double horizon) {
  return circle_contact(b.p - a.p, b.v - a.v, 0.5 * (b.a - a.a), distance, horizon);
}

double cushion_reach(double ball_radius, double nose_height) { return nose_reach(ball_radius, nose_height); }

NoseLine nose_line(const Rail& rail) {
  NoseLine line;
  line.rail = rail;
  const Vec3 along(rail.b.x() - rail.a.x(), rail.b.y() - rail.a.y(), 0);
  line.length = along.norm();
  if (line.length == 0) return line;
  line.dir = along / line.length;
  line.inward = Vec3(line.dir.y(), -line.dir.x(), 0);  // the playing side: right of a -> b
  return line;
}

std::optional<double> next_ball_cushion(const Path& ball, const Rail& rail, double reach, double horizon) {
  return next_ball_cushion(ball, nose_line(rail), reach, horizon);
}

std::optional<double> next_ball_cushion(const Path& ball, const NoseLine& line, double reach, double horizon) {
  const Rail& rail = line.rail;
  const double length = line.length;
  if (length == 0) return std::nullopt;
  const Vec3& dir = line.dir;
  const Vec3& inward = line.inward;
  const Vec3 rel(ball.p.x() - rail.a.x(), ball.p.y() - rail.a.y(), 0);
  // s(t): distance of the centre from the nose line beyond the contact reach.
  Poly s{{inward.dot(rel) - reach, inward.dot(ball.v), 0.5 * inward.dot(ball.a), 0, 0}};
  if (s.c[0] < -reach) return std::nullopt;  // behind the cushion
  auto on_segment = [&](double t) {
    const double u = dir.dot(Vec3(ball.at(t).x() - rail.a.x(), ball.at(t).y() - rail.a.y(), 0));
    return u >= 0 && u <= length;
  };
  // A centre level with the nose line or beyond it but past the line's end (in a cut pocket's mouth, as
  // after a ball glances off the other jaw's rounding) does not touch this cushion: its s < 0 is no
  // overlap. Read as one (first_contact's push rules), the contact would wait until s came back down to
  // that depth, by then on the segment and as deep inside the nose. Such a ball meets the line only by
  // coming down through s = 0 after rising above it; entering the segment's span while still below
  // s = 0, it meets the rounding of the jaw point first (table.h, PocketMouth: the nose line ends where
  // that rounding begins) or the cushion's end (next_ball_point).
  const std::optional<double> top =
      s.c[0] <= kTouchDistance && !on_segment(0) ? rises_to_top(s, horizon) : std::nullopt;
  std::optional<double> t;
  if (top)
    t = first_descent(s, *top, horizon);
  else if (s.c[0] <= kTouchDistance && -s.c[1] > kMinClosingSpeed)
    t = on_segment(0) ? std::optional<double>(0.0) : std::nullopt;
  else
    t = first_contact(s, s.c[0], -s.c[1], horizon, [](double x) { return -x; });
  // Past the end points the ball meets the cushion's end (next_ball_point) first.
  if (t && on_segment(*t)) return t;
  return std::nullopt;
}

std::optional<double> next_ball_point(const Path& ball, const Vec3& point, double reach, double horizon) {
  return circle_contact(ball.p - point, ball.v, 0.5 * ball.a, reach, horizon);
}

std::optional<double> next_pocket_entry(const Path& ball, const Pocket& pocket, double horizon) {
  const Poly f = circle_gap(ball.p - pocket.center, ball.v, 0.5 * ball.a, pocket.radius);
  if (f.c[0] <= 0) return 0.0;  // over the hole already: it drops at once
  return first_descent(f, 0, horizon);
}

}  // namespace bsim
