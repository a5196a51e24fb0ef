#pragma once
// The effective target of a pocket (Dr. Dave Alciatore, TP 3.5 side, TP 3.6 corner): the total width of
// the parallel lines along which a lone ball, rolling in at one angle, drops into the pocket. Measured
// here as the `pocket_bench` bench and tests/physics/test_pockets.cpp measure it, through the physics
// itself (simulate_events), one line at a time.
//
// A sweep: the top-right corner (pocket 2) or the top side pocket (pocket 1) of the standard table. The
// lines run at `angle_deg` from the pocket's axis (a corner's bisector, a side pocket's perpendicular to
// the rail), turned toward +x, so that at the steep angles a corner's lines run along the long rail, as on
// Dr. Dave's table, and a side pocket's come from the -x half. They lie `step` apart, offset across their
// direction from the line through the middle of the mouth (+ toward the jaw the ball passes first), from
// `min_offset` to `max_offset` (further out on the + side, where a corner's lines along the long rail meet
// it first and still pot). On each line the ball rolls (its spin set for natural roll) from `run_up`
// before the point abreast of the mouth's middle, with the speed that leaves it `speed` there had it
// rolled straight on (v0^2 = v^2 + 2 a d, a the rolling deceleration). Where the table ends sooner the
// ball starts on the line inside the table instead (its centre one margin clear of the reach of every
// nose line, and clear of every pocket's throat), still with the speed for the distance it has left; a
// line that meets a rail before the mouth counts if the ball then drops into the pocket, as Dr. Dave's
// corner model counts rail-first entries, as long as every rail it meets lies along that one cushion and
// comes before the pocket's jaws (a ball that drops after a bank, off a second cushion or out of the jaws
// and back, is no line into the pocket). A line that never crosses the table does not pot.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "detect.h"
#include "random_scenes.h"
#include "simulate.h"
#include "table.h"

namespace bsim::pockets {

inline constexpr double kInch = 0.0254;

/// Dr. Dave's effective targets, in inches, for slow shots (TP 3.6 corner with a 4.5875 in mouth; TP 3.5
/// side with 5.0625 in), as research/pockets_rules.md A2 tabulates them: the angles the bench sweeps.
struct DrDavePoint {
  double angle_deg;
  double target_in;
};
inline constexpr DrDavePoint kDrDaveCorner[] = {{0, 2.67},  {10, 2.61}, {20, 2.43}, {30, 2.32},
                                                {35, 2.68}, {40, 2.94}, {44, 2.95}};
/// No ball drops beyond 68.292 deg (TP 3.5's theta_max); 68.3 and 70 deg are 0.
inline constexpr DrDavePoint kDrDaveSide[] = {{0, 3.23},  {20, 2.96}, {30, 2.63},  {40, 2.18}, {50, 1.57},
                                              {60, 0.69}, {65, 0.33}, {68.3, 0.0}, {70, 0.0}};

/// The tables a sweep runs on.
enum class Geometry {
  standard,  ///< the standard table as scenes have it: jaw points rounded 5 mm, corner shelf 41.3 mm
  /// Dr. Dave's pockets: sharp jaw points and his 1.125 in corner shelf (`param jaw_radius 0`, `param
  /// corner_shelf 0.028575`; his hole radii, mouths and side shelf are the standard table's already).
  dr_dave_pockets,
  /// Dr. Dave's plane model: his pockets, and the noses at the ball's equator, so that a ball meets the
  /// noses and the jaws with its centre R from them, as his ball does (on the standard table the noses
  /// stand 36.3 mm high and meet the ball above its equator, its centre 27.5 mm from them).
  dr_dave_plane,
  bare,  ///< the standard table with the drop circles alone (bare_standard_pockets): no jaws, no shelf
};

inline const char* geometry_name(Geometry g) {
  switch (g) {
    case Geometry::standard: return "standard table";
    case Geometry::dr_dave_pockets: return "Dr. Dave's pockets";
    case Geometry::dr_dave_plane: return "Dr. Dave's plane model";
    case Geometry::bare: return "bare drop circles";
  }
  return "";
}

inline PhysicsParams geometry_params(Geometry g) {
  PhysicsParams p;
  if (g == Geometry::dr_dave_pockets || g == Geometry::dr_dave_plane) {
    p.jaw_radius = 0;
    p.corner_shelf = 1.125 * kInch;
  }
  return p;
}

/// The table of geometry `g`, no balls.
inline Scene pocket_table(Geometry g) {
  Scene scene;
  scene.physics = geometry_params(g);
  scene.rails = standard_rails(scene.physics);
  if (g == Geometry::dr_dave_plane)
    for (Rail& r : scene.rails) r.a.z() = r.b.z() = scene.physics.ball_radius;
  scene.pockets = g == Geometry::bare ? bare_standard_pockets() : standard_pockets(scene.physics);
  return scene;
}

struct SweepSpec {
  Geometry geometry = Geometry::standard;
  PocketKind kind = PocketKind::corner;
  double angle_deg = 0;       ///< from the pocket's axis, turned toward +x
  double speed = 0.5;         ///< m/s, rolling, abreast of the mouth's middle
  double step = 0.00025;      ///< m between neighbouring lines
  double min_offset = -0.15;  ///< m, the offsets swept, from this
  double max_offset = 0.30;   ///< m, to this
  double run_up = 1.0;        ///< m rolled before the mouth where the table allows
  double margin = 0.001;      ///< m a start stays clear of the nose lines' reach and the throats
};

/// The pocket a sweep of `kind` crosses: the top-right corner (2) or the top side pocket (1).
inline int swept_pocket(PocketKind kind) { return kind == PocketKind::side ? 1 : 2; }

/// The line's unit direction into the pocket and its unit offset direction (+ toward the first jaw).
struct LineFrame {
  Vec3 middle{0, 0, 0};  ///< the mouth's middle (the cut pocket's, for a bare table too)
  Vec3 along{1, 0, 0};
  Vec3 across{0, 1, 0};
};

inline LineFrame line_frame(const SweepSpec& spec) {
  const Pocket pocket =
      standard_pockets(geometry_params(spec.geometry))[static_cast<std::size_t>(swept_pocket(spec.kind))];
  const double turn = -spec.angle_deg * std::numbers::pi / 180;  // clockwise: toward +x from the top pockets
  const Vec3 axis = pocket.axis;
  LineFrame f;
  f.middle = (pocket.jaw[0] + pocket.jaw[1]) / 2;
  f.along = Vec3(std::cos(turn) * axis.x() - std::sin(turn) * axis.y(),
                 std::sin(turn) * axis.x() + std::cos(turn) * axis.y(), 0);
  f.across = Vec3(-f.along.y(), f.along.x(), 0);
  return f;
}

/// Where a ball may start: inside every nose line's reach by the margin, and clear of every pocket's
/// opening (its drop circle and its throat, grown by the ball's radius and the margin).
class StartArea {
 public:
  StartArea(const Scene& table, double margin) : R_(table.physics.ball_radius), margin_(margin) {
    const TableSpec& t = kStandardTable;
    const double reach = cushion_reach(R_, table.rails.front().a.z()) + margin;
    x_ = t.half_length - reach;
    y_ = t.half_width - reach;
    for (const Pocket& pocket : table.pockets) mouths_.push_back(pocket_mouth(pocket, table.rails));
  }
  /// The stretch of s (m) where p - s u lies inside the nose lines' reach; none when it misses.
  std::optional<std::pair<double, double>> inside(const Vec3& p, const Vec3& u) const {
    double lo = -1e9, hi = 1e9;
    const double half[2] = {x_, y_};
    for (int k = 0; k < 2; ++k) {
      const double c = p[k], d = -u[k];
      if (std::abs(d) < 1e-15) {
        if (std::abs(c) > half[k]) return std::nullopt;
        continue;
      }
      double a = (-half[k] - c) / d, b = (half[k] - c) / d;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a);
      hi = std::min(hi, b);
    }
    if (lo > hi) return std::nullopt;
    return std::pair{lo, hi};
  }
  bool clear_of_pockets(const Vec3& p) const {
    for (const PocketMouth& m : mouths_) {
      if ((flat(p) - m.centre).norm() < m.drop_radius + R_ + margin_) return false;
      if (m.in_throat(p, R_ + margin_)) return false;
    }
    return true;
  }

 private:
  double R_, margin_;
  double x_ = 0, y_ = 0;
  std::vector<PocketMouth> mouths_;
};

/// The lone ball rolling on line `offset` (m) of the sweep, on `table`; none when the line never
/// crosses the table.
inline std::optional<Scene> line_scene(const Scene& table, const SweepSpec& spec, double offset) {
  const PhysicsParams& params = table.physics;
  const LineFrame f = line_frame(spec);
  const Vec3 through = f.middle + offset * f.across;
  auto at = [&](double s) { return Vec3(through.x() - s * f.along.x(), through.y() - s * f.along.y(), 0); };
  // s: m back from abreast of the mouth's middle. The run-up, clamped to the line's stretch on the table,
  // then moved toward that stretch's middle (1 mm at a time) until clear of every pocket.
  const StartArea area(table, spec.margin);
  const auto inside = area.inside(through, f.along);
  if (!inside) return std::nullopt;
  const auto [lo, hi] = *inside;
  double back = std::clamp(spec.run_up, lo, hi);
  const double toward = (lo + hi) / 2 > back ? 0.001 : -0.001;
  while (!area.clear_of_pockets(at(back))) {
    back += toward;
    if (back < lo || back > hi) return std::nullopt;
  }
  const double v0 = std::sqrt(spec.speed * spec.speed + 2 * params.roll_decel() * std::max(back, 0.0));
  Scene scene = table;
  const Vec3 start = at(back);
  const Vec3 velocity = v0 * f.along;
  Ball ball = scenes::ball_at(0, start.x(), start.y(), params, velocity);
  ball.spin = Vec3(0, 0, 1).cross(velocity) / params.ball_radius;  // natural roll
  scene.balls.push_back(ball);
  return scene;
}

/// What one line did.
struct LineOutcome {
  bool exists = false;   ///< the line crosses the table
  bool dropped = false;  ///< the ball dropped into the swept pocket
  bool potted = false;   ///< and it counts: every rail it met before lies along one cushion line
  int jaw_hits = 0;      ///< its ball-jaw events before it dropped (or in all)
  int rail_hits = 0;     ///< its ball-rail events before it dropped (or in all)
};

/// Whether two rails' nose lines lie along one line (the two halves of a long cushion).
inline bool collinear(const Rail& a, const Rail& b) {
  const Vec3 d = flat(a.b - a.a).normalized();
  auto off = [&](const Vec3& p) { return std::abs(d.x() * (p.y() - a.a.y()) - d.y() * (p.x() - a.a.x())); };
  return off(b.a) < 1e-9 && off(b.b) < 1e-9;
}

/// The line's outcome from its simulation: a drop into the swept pocket counts when the ball met no rail
/// before it, or only rails along the cushion it met first and before the pocket's jaws (a rail-first
/// entry, or a ball clinging to the rail); a ball that drops after a bank (out of the jaws and back, or off
/// a second cushion) does not count.
inline LineOutcome line_outcome(const Scene& scene, const SimulationResult& result, int pocket) {
  LineOutcome out;
  out.exists = true;
  double drop = 1e300;
  for (const PocketDrop& d : result.drops)
    if (d.pocket == pocket) {
      out.dropped = true;
      drop = d.time;
    }
  int first_rail = -1;
  bool counts = true, jawed = false;
  for (const Event& e : result.events) {
    if (e.time > drop) break;
    if (e.type == EventType::ball_jaw) {
      ++out.jaw_hits;
      jawed = jawed || e.pocket == pocket;
    }
    if (e.type != EventType::ball_rail) continue;
    ++out.rail_hits;
    if (first_rail < 0) first_rail = e.rail;
    // Out of the pocket's jaws and back, or off a second cushion: a bank, no line into the pocket.
    counts =
        counts && !jawed &&
        collinear(scene.rails[static_cast<std::size_t>(first_rail)], scene.rails[static_cast<std::size_t>(e.rail)]);
  }
  out.potted = out.dropped && counts;
  return out;
}

inline LineOutcome roll_line(const Scene& table, const SweepSpec& spec, double offset) {
  const std::optional<Scene> scene = line_scene(table, spec, offset);
  if (!scene) return {};
  return line_outcome(*scene, simulate_events(*scene), swept_pocket(spec.kind));
}

struct SweepResult {
  double target = 0;            ///< m, the total width of the lines that pot (potting lines times the step)
  double centre = 0;            ///< m, the potting lines' mean offset (+ toward the first jaw)
  int bands = 0;                ///< runs of neighbouring potting lines (1: one unbroken target)
  int lines = 0;                ///< lines rolled (crossing the table)
  int potted = 0;               ///< of which potted
  int potted_via_jaw = 0;       ///< potted after touching a jaw
  int potted_via_rail = 0;      ///< potted after a rail first
  int dropped_uncounted = 0;    ///< dropped after a bank off another cushion (not counted)
  std::vector<double> offsets;  ///< m, each potting line's offset, ascending
  bool truncated = false;       ///< a line at either end of the range pots: the target may run on beyond it
};

/// The sweep on its geometry's table.
inline SweepResult sweep(const SweepSpec& spec) {
  const Scene table = pocket_table(spec.geometry);
  SweepResult r;
  const auto first = static_cast<int>(std::ceil(spec.min_offset / spec.step - 1e-9));
  const auto end = static_cast<int>(std::floor(spec.max_offset / spec.step + 1e-9));
  bool last = false;
  double sum = 0;
  for (int k = first; k <= end; ++k) {
    const double offset = k * spec.step;
    const LineOutcome o = roll_line(table, spec, offset);
    r.lines += o.exists ? 1 : 0;
    r.dropped_uncounted += o.dropped && !o.potted ? 1 : 0;
    if (o.potted) {
      ++r.potted;
      r.potted_via_jaw += o.jaw_hits > 0 ? 1 : 0;
      r.potted_via_rail += o.rail_hits > 0 ? 1 : 0;
      r.offsets.push_back(offset);
      sum += offset;
      if (!last) ++r.bands;
      r.truncated = r.truncated || k == first || k == end;
    }
    last = o.potted;
  }
  r.target = r.potted * spec.step;
  r.centre = r.potted ? sum / r.potted : 0;
  return r;
}

}  // namespace bsim::pockets
