#include "cue_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "camera_view.h"
#include "cue_pose.h"
#include "table.h"

namespace bsim {

namespace {
/// m between points tested against the cushions and the view: finer than the stick is thick.
constexpr double kAxisStep = 0.01;
/// m between points tested against the view cone, whose margin covers the stick's thickness.
constexpr double kViewStep = 0.05;
/// deg added to the view cone so that a stick half inside the border still counts as seen.
constexpr double kViewMarginDeg = 3.0;

/// Lowest point of the circular cross-section at `centre`, perpendicular to `axis`.
double lowest_z(const Vec3& centre, const Vec3& axis, double radius) {
  return centre.z() - radius * std::sqrt(std::max(0.0, 1.0 - axis.z() * axis.z()));
}

/// Points on the lower half of the stick's round, at each sample of its axis, tested against the wood.
constexpr int kUnderPoints = 9;
/// m ahead of the camera from which the stick's outline in the picture is measured (a stick nearer
/// than that covers the picture anyway, and would project without bound).
constexpr double kShareNear = 0.05;
/// Points round each end of the stick whose projections outline it in the picture.
constexpr int kOutlinePoints = 24;
/// m between the points of the stick's axis tested against a line of sight.
constexpr double kSightStep = 0.005;

/// The convex hull of `points`, anticlockwise (Andrew's monotone chain).
std::vector<PicturePoint> convex_hull(std::vector<PicturePoint> points) {
  std::sort(points.begin(), points.end(),
            [](const PicturePoint& a, const PicturePoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](const PicturePoint& o, const PicturePoint& a, const PicturePoint& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  if (points.size() < 3) return points;
  std::vector<PicturePoint> hull(2 * points.size());
  std::size_t k = 0;
  for (const PicturePoint& p : points) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

/// `polygon` clipped to the picture (-1..1 both ways; Sutherland and Hodgman's clipping).
std::vector<PicturePoint> clip_to_picture(std::vector<PicturePoint> polygon) {
  // Each edge of the picture as the coordinate it bounds (0: x, 1: y) and its side (+1: at most 1, -1: at least -1).
  for (const auto& edge : {std::pair{0, 1.0}, std::pair{0, -1.0}, std::pair{1, 1.0}, std::pair{1, -1.0}}) {
    const int axis = edge.first;  // lambdas capture variables, not structured bindings
    const double sign = edge.second;
    const auto inside = [&](const PicturePoint& p) { return sign * (axis == 0 ? p.x : p.y) <= 1.0; };
    const auto cross = [&](const PicturePoint& a, const PicturePoint& b) {
      const double va = axis == 0 ? a.x : a.y, vb = axis == 0 ? b.x : b.y;
      const double f = (sign - va) / (vb - va);
      return PicturePoint{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
    };
    std::vector<PicturePoint> out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const PicturePoint& a = polygon[i];
      const PicturePoint& b = polygon[(i + 1) % polygon.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) out.push_back(cross(a, b));
    }
    polygon = std::move(out);
  }
  return polygon;
}

double area(const std::vector<PicturePoint>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const PicturePoint& a = polygon[i];
    const PicturePoint& b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::abs(twice);
}

/// What stands round the bed for the stick to clear, seen from above: the blocks behind the cushions'
/// noses (cushion and wood), within the table's frame, less the pockets' openings.
struct Blocks {
  TableRect frame;                    ///< the table's outer edge
  std::vector<PocketMouth> openings;  ///< each pocket's opening through the cushions and the wood

  /// Whether plan point q of a block `length` m long (a rail from a, along `along`, its back `outward`)
  /// is solid: behind the nose, within the cushion and wood, in the frame and in no pocket's opening.
  bool solid(const Vec3& q, const Vec3& a, const Vec3& along, const Vec3& outward, double length) const {
    const double reach = kStandardTable.rail_reach();
    const double out = (q - a).dot(outward), at = (q - a).dot(along);
    // Past the rail's ends the block reaches on round the table's corner (the frame bounds it).
    if (out < 0 || out > reach || at < -2 * reach || at > length + 2 * reach) return false;
    if (q.x() < frame.x0 || q.x() > frame.x1 || q.y() < frame.y0 || q.y() > frame.y1) return false;
    return std::none_of(openings.begin(), openings.end(), [&](const PocketMouth& m) { return m.in_throat(q); });
  }
};

double cushion_gap(const CuePose& stick, const Rail& rail, const Blocks& blocks) {
  const Vec3 a(rail.a.x(), rail.a.y(), 0), b(rail.b.x(), rail.b.y(), 0);
  const double length = (b - a).norm();
  if (!(length > 0)) return std::numeric_limits<double>::infinity();
  const Vec3 along = (b - a) / length;
  const Vec3 outward(-along.y(), along.x(), 0);  // playing side is on the right of a -> b
  // The block behind the nose: cushion and wood, up to the wood's top (above the cushion's).
  const double top = 0.5 * (rail.a.z() + rail.b.z()) + kStandardTable.rail.top_rise;
  const double reach = kStandardTable.rail_reach();
  // Across the stick: level and square to it, and square to both, downwards.
  Vec3 side = stick.axis.cross(Vec3::UnitZ());
  side = side.norm() > 1e-9 ? Vec3(side.normalized()) : Vec3::UnitX();
  Vec3 down = stick.axis.cross(side).normalized();
  if (down.z() > 0) down = -down;
  double gap = std::numeric_limits<double>::infinity();
  for (double s = 0; s <= kCueLength + 1e-9; s += kAxisStep) {
    const Vec3 point = stick.tip + s * stick.axis;
    const double radius = stick_radius(s);
    const double out = (flat(point) - a).dot(outward), at = (flat(point) - a).dot(along);
    if (out < -radius || out > reach + radius || at < -2 * reach - radius || at > length + 2 * reach + radius) continue;
    // The stick's underside, from one side round the bottom to the other: each of its points over the
    // solid must clear the wood's top.
    for (int k = 0; k < kUnderPoints; ++k) {
      const double angle = std::numbers::pi * k / (kUnderPoints - 1);
      const Vec3 p = point + radius * (std::cos(angle) * side + std::sin(angle) * down);
      if (blocks.solid(flat(p), a, along, outward, length)) gap = std::min(gap, p.z() - top);
    }
  }
  return gap;
}
}  // namespace

double stick_radius(double s) {
  const double f = std::clamp(s / kCueLength, 0.0, 1.0);
  return kCueTipRadius + f * (kCueButtRadius - kCueTipRadius);
}

double stick_ball_gap(const CuePose& stick, const Vec3& centre, double ball_radius) {
  const Vec3 w = centre - stick.tip;
  const double s = w.dot(stick.axis);
  const double off_axis = (w - s * stick.axis).norm();
  // In front of the tip face or behind the butt: distance to the end disc.
  if (s < 0) return std::hypot(s, std::max(0.0, off_axis - kCueTipRadius)) - ball_radius;
  if (s > kCueLength) return std::hypot(s - kCueLength, std::max(0.0, off_axis - kCueButtRadius)) - ball_radius;
  // Beside the rod: the taper is so slight (0.3 deg) that the radial gap is the distance.
  return off_axis - stick_radius(s) - ball_radius;
}

double stick_clearance(const CuePose& stick, const Scene& scene, const std::vector<BallState>& balls,
                       double ball_radius, int skip) {
  const Vec3 butt = stick.tip + kCueLength * stick.axis;
  double gap = std::min(lowest_z(stick.tip, stick.axis, kCueTipRadius), lowest_z(butt, stick.axis, kCueButtRadius));
  const TableLayout layout = table_layout(scene);
  const Blocks blocks{layout.wood_outer, layout.pockets};
  for (const Rail& rail : scene.rails) gap = std::min(gap, cushion_gap(stick, rail, blocks));
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (static_cast<int>(i) == skip || balls[i].motion == Motion::pocketed) continue;
    gap = std::min(gap, stick_ball_gap(stick, balls[i].position, ball_radius));
  }
  return gap;
}

bool stick_in_view(const CuePose& stick, const CameraPose& camera) {
  const CameraView view(camera);
  const double cone = view.cone_half_angle_deg() + kViewMarginDeg;
  for (double s = 0; s <= kCueLength + 1e-9; s += kViewStep) {
    if (view.in_cone(stick.tip + s * stick.axis, cone)) return true;
  }
  return false;
}

double stick_picture_share(const CuePose& stick, const CameraPose& camera) {
  const CameraView view(camera);
  // The stretch of the axis at least kShareNear ahead of the camera (its depth is linear along it).
  const double d0 = view.depth(stick.tip), d1 = view.depth(stick.tip + kCueLength * stick.axis);
  double s0 = 0, s1 = kCueLength;
  if (d0 < kShareNear && d1 < kShareNear) return 0;
  if (d0 < kShareNear) s0 = kCueLength * (kShareNear - d0) / (d1 - d0);
  if (d1 < kShareNear) s1 = kCueLength * (kShareNear - d0) / (d1 - d0);
  // The rod between them is a truncated cone: its outline is the hull of its two end circles.
  const Vec3 u = stick.axis.unitOrthogonal(), v = stick.axis.cross(u);
  std::vector<PicturePoint> points;
  for (const double s : {s0, s1})
    for (int k = 0; k < kOutlinePoints; ++k) {
      const double a = 2 * std::numbers::pi * k / kOutlinePoints;
      const Vec3 p = stick.tip + s * stick.axis + stick_radius(s) * (std::cos(a) * u + std::sin(a) * v);
      if (const std::optional<PicturePoint> at = view.project(p)) points.push_back(*at);
    }
  return area(clip_to_picture(convex_hull(std::move(points)))) / 4.0;  // the picture is 2 by 2
}

bool stick_hides(const CuePose& stick, const CameraPose& camera, const Vec3& p, double radius) {
  const Vec3 sight = p - camera.location;
  const double reach = sight.norm();
  if (!(reach > radius)) return false;
  const Vec3 along = sight / reach;
  for (double s = 0; s <= kCueLength + 1e-9; s += kSightStep) {
    const Vec3 q = stick.tip + s * stick.axis;
    const double ahead = (q - camera.location).dot(along);
    if (ahead <= 0 || ahead >= reach - radius) continue;
    // Half the ball's radius, seen from the camera, at the stick's distance.
    if ((q - camera.location - ahead * along).norm() < stick_radius(s) + 0.5 * radius * ahead / reach) return true;
  }
  return false;
}

}  // namespace bsim
