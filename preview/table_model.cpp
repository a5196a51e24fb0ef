#include "table_model.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "pocket_fall.h"
#include "table.h"

namespace bsim {

namespace {

// The cushion, the wood, the sights and the floor come from the table description (kStandardTable,
// table_layout); what follows is drawing detail.
constexpr double kNoseRound = 0.008;    // m outward from the nose where the profile reaches the cushion's top
constexpr double kSquareSlope = 0.6;    // a cushion end at no pocket recedes this much per metre of depth
constexpr double kApronBottom = -0.22;  // m
constexpr double kLegSize = 0.12;       // m
// m below the bed: the cup's floor, where the physics leaves a pocketed ball (its bottom kPocketDepth
// down), as POV-Ray's CupFloorZ.
constexpr double kCupFloor = -kPocketDepth - 0.0005;
constexpr int kHoleSegments = 48;
constexpr int kRoundSteps = 4;       // pieces of a jaw point's rounding, and of the slate's lip
constexpr int kBackSteps = 6;        // pieces of a cushion's end cut round the hole behind its facing
constexpr double kCell = 0.06;       // m, tessellation of the table for its per-vertex lighting
constexpr double kFloorCell = 0.25;  // m

Vec3 wood_color() { return srgb(96, 42, 18); }
Vec3 apron_color() { return srgb(70, 30, 14); }
Vec3 liner_color() { return srgb(22, 18, 16); }
Vec3 hole_color() { return srgb(6, 6, 6); }
Vec3 leather_color() { return srgb(17, 10, 6); }  // the near-black pocket leather, as POV-Ray's
Vec3 sight_color() { return srgb(236, 228, 206); }

using Bounds = TableRect;

// How one end of a cushion is cut, seen from above: how far past its end point (along the nose, into
// the pocket if it has one) the cushion reaches at each depth behind its nose. A cut pocket's jaw (the
// physics' own) is rounded from the nose into the facing, follows the facing and, behind it, the hole's
// edge; a bare pocket's jaw is the facing's plane alone; an end at no pocket is square, receding.
class EndCut {
 public:
  /// `away` points from the end past it (towards its pocket, if any); `out` away from the bed.
  EndCut(const Vec3& end, const Vec3& away, const Vec3& out, const CushionEnd& cut, const TableLayout& layout)
      : slant_(cut.pocket >= 0 ? cut.slant : -kSquareSlope) {
    if (cut.pocket < 0) return;
    const PocketMouth& m = layout.pockets[static_cast<std::size_t>(cut.pocket)];
    const int jaw = (flat(m.nose[0]) - end).norm() <= (flat(m.nose[1]) - end).norm() ? 0 : 1;
    if (!m.cut) return;
    cut_ = true;
    const auto local = [&](const Vec3& p) { return Vec3((p - end).dot(away), (p - end).dot(out), 0); };
    round_ = local(m.round_centre[jaw]);
    round_radius_ = m.round_radius;
    face_depth_ = local(m.face_start[jaw]).y();
    hole_ = local(m.centre);
    hole_radius_ = m.drop_radius;
    tangent_depth_ = local(m.tangent[jaw]).y();
  }

  double reach(double depth) const {
    double s = slant_ * depth;
    if (!cut_) return s;
    if (round_radius_ > 0 && depth < face_depth_) {
      const double d = depth - round_.y();
      s = std::min(s, round_.x() + std::sqrt(std::max(0.0, round_radius_ * round_radius_ - d * d)));
    }
    const double h = depth - hole_.y();
    if (std::abs(h) < hole_radius_) s = std::min(s, hole_.x() - std::sqrt(hole_radius_ * hole_radius_ - h * h));
    return s;
  }

  /// Depths in (0, width) where the cut bends, its curved parts sampled.
  std::vector<double> bends(double width) const {
    std::vector<double> depths;
    if (!cut_) return depths;
    for (int k = 1; k <= kRoundSteps; ++k) depths.push_back(face_depth_ * k / kRoundSteps);
    const double back = std::min(width, hole_.y() + hole_radius_);
    for (int k = 0; k <= kBackSteps; ++k) depths.push_back(tangent_depth_ + (back - tangent_depth_) * k / kBackSteps);
    std::erase_if(depths, [&](double d) { return !(d > 1e-6 && d < width - 1e-6); });
    return depths;
  }

 private:
  double slant_;
  bool cut_ = false;
  Vec3 round_{0, 0, 0}, hole_{0, 0, 0};  // (along `away`, depth) from the end
  double round_radius_ = 0, face_depth_ = 0, hole_radius_ = 0, tangent_depth_ = 0;
};

struct ProfilePoint {
  double offset, height;  ///< m behind the nose, m above the bed
};

/// The cushion's cross-section from its foot up to the nose and back over its top to the wood, cut
/// at each of `bends` it spans, so that an end cut along a curve meets the faces at their edges.
std::vector<ProfilePoint> cushion_profile(double nose, double top, std::vector<double> bends) {
  const CushionProfile& cushion = kStandardTable.cushion;
  const ProfilePoint corners[] = {{cushion.undercut, 0}, {0, nose}, {kNoseRound, top}, {cushion.width, top}};
  std::sort(bends.begin(), bends.end());
  std::vector<ProfilePoint> profile{corners[0]};
  for (int k = 0; k + 1 < 4; ++k) {
    const ProfilePoint p = corners[k], q = corners[k + 1];
    std::vector<double> inside;
    for (double b : bends)
      if (b > std::min(p.offset, q.offset) + 1e-9 && b < std::max(p.offset, q.offset) - 1e-9) inside.push_back(b);
    if (q.offset < p.offset) std::reverse(inside.begin(), inside.end());
    for (double b : inside)
      profile.push_back({b, p.height + (q.height - p.height) * (b - p.offset) / (q.offset - p.offset)});
    profile.push_back(q);
  }
  return profile;
}

/// The end of a cushion as upright strips from the bed (or its undercut foot) to the profile's top,
/// between each two depths of the profile: flat for a straight cut, following a curved one.
void add_cushion_end(MeshData& body, const std::vector<ProfilePoint>& profile, double nose,
                     const std::function<Vec3(const ProfilePoint&)>& at, const Vec3& color) {
  const CushionProfile& cushion = kStandardTable.cushion;
  std::vector<double> depths;
  for (const ProfilePoint& p : profile) depths.push_back(p.offset);
  std::sort(depths.begin(), depths.end());
  depths.erase(std::unique(depths.begin(), depths.end()), depths.end());
  const auto low = [&](double o) { return o < cushion.undercut ? nose * (1 - o / cushion.undercut) : 0.0; };
  const auto high = [&](double o) {
    for (std::size_t k = 1; k < profile.size(); ++k) {
      const ProfilePoint p = profile[k - 1], q = profile[k];
      if (q.offset > p.offset && o >= p.offset && o <= q.offset)
        return p.height + (q.height - p.height) * (o - p.offset) / (q.offset - p.offset);
    }
    return nose;
  };
  for (std::size_t k = 0; k + 1 < depths.size(); ++k) {
    const double o0 = depths[k], o1 = depths[k + 1];
    body.add_quad(at({o0, low(o0)}), at({o1, low(o1)}), at({o1, high(o1)}), at({o0, high(o0)}), color);
  }
}

// A cushion: its profile swept along the nose line, each end cut as EndCut says.
void add_cushion(MeshData& body, const Rail& rail, double top, const CushionEnd& end_a, const CushionEnd& end_b,
                 const TableLayout& layout) {
  Vec3 d = rail.b - rail.a;
  d.z() = 0;
  const double length = d.norm();
  if (length < 1e-6) return;
  d /= length;
  const Vec3 out(-d.y(), d.x(), 0);  // the playing side is on the right of a -> b
  const double nose = rail.a.z();
  const Vec3 a = flat(rail.a), b = flat(rail.b);
  const EndCut cut_a(a, -d, out, end_a, layout), cut_b(b, d, out, end_b, layout);
  std::vector<double> bends = cut_a.bends(kStandardTable.cushion.width);
  for (double o : cut_b.bends(kStandardTable.cushion.width)) bends.push_back(o);
  const std::vector<ProfilePoint> profile = cushion_profile(nose, top, bends);
  const auto at = [&](const Vec3& end, const Vec3& away, const EndCut& cut, const ProfilePoint& p) {
    return Vec3(end + out * p.offset + away * cut.reach(p.offset) + Vec3(0, 0, p.height));
  };
  const Vec3 cloth = cloth_color() * 0.85;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k)
    body.add_quad(at(a, -d, cut_a, profile[k]), at(b, d, cut_b, profile[k]), at(b, d, cut_b, profile[k + 1]),
                  at(a, -d, cut_a, profile[k + 1]), cloth, kCell);
  const auto at_a = [&](const ProfilePoint& p) { return at(a, -d, cut_a, p); };
  const auto at_b = [&](const ProfilePoint& p) { return at(b, d, cut_b, p); };
  add_cushion_end(body, profile, nose, at_a, cloth);
  add_cushion_end(body, profile, nose, at_b, cloth);
}

// A ring-shaped top face between an outer rectangle and an inner one, as four trapezoids.
void add_frame_ring(MeshData& mesh, const Bounds& inner, const Bounds& outer, double z, const Vec3& color) {
  const Vec3 i0(inner.x0, inner.y0, z), i1(inner.x1, inner.y0, z), i2(inner.x1, inner.y1, z), i3(inner.x0, inner.y1, z);
  const Vec3 o0(outer.x0, outer.y0, z), o1(outer.x1, outer.y0, z), o2(outer.x1, outer.y1, z), o3(outer.x0, outer.y1, z);
  mesh.add_quad(o0, o1, i1, i0, color, kCell);
  mesh.add_quad(o1, o2, i2, i1, color, kCell);
  mesh.add_quad(o2, o3, i3, i2, color, kCell);
  mesh.add_quad(o3, o0, i0, i3, color, kCell);
}

bool inside_any_throat(const TableLayout& layout, const Vec3& p, double grow) {
  for (const PocketMouth& m : layout.pockets)
    if (m.in_throat(p, grow)) return true;
  return false;
}

/// Where along the segment p -> q (as fractions, 0 and 1 included) it enters or leaves a pocket's
/// throat grown by `grow`: found to a micrometre, so a wall cut there meets the pocket's liner.
std::vector<double> throat_crossings(const TableLayout& layout, const Vec3& p, const Vec3& q, double grow) {
  constexpr int kSamples = 1000;  // a few mm apart along a side: far closer than any two crossings
  std::vector<double> cuts{0.0};
  const auto inside = [&](double t) { return inside_any_throat(layout, p + (q - p) * t, grow); };
  bool was = inside(0);
  for (int k = 1; k <= kSamples; ++k) {
    double lo = static_cast<double>(k - 1) / kSamples, hi = static_cast<double>(k) / kSamples;
    if (inside(hi) == was) continue;
    while ((hi - lo) * (q - p).norm() > 1e-6) {
      const double mid = (lo + hi) / 2;
      (inside(mid) == was ? lo : hi) = mid;
    }
    cuts.push_back(hi);
    was = !was;
  }
  cuts.push_back(1.0);
  return cuts;
}

// Vertical walls around a rectangle in pieces of at most kCell, leaving out what lies in a pocket's
// throat (grown by its liner): each side is cut exactly where it enters and leaves a throat.
void add_walls(MeshData& mesh, const Bounds& r, double z0, double z1, const Vec3& color, const TableLayout* cut_by) {
  const Vec3 c[4] = {{r.x0, r.y0, 0}, {r.x1, r.y0, 0}, {r.x1, r.y1, 0}, {r.x0, r.y1, 0}};
  for (int k = 0; k < 4; ++k) {
    const Vec3& p = c[k];
    const Vec3& q = c[(k + 1) % 4];
    const std::vector<double> cuts =
        cut_by ? throat_crossings(*cut_by, p, q, kStandardTable.jaws.liner) : std::vector<double>{0.0, 1.0};
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const Vec3 a = p + (q - p) * cuts[i], b = p + (q - p) * cuts[i + 1];
      if (cut_by && inside_any_throat(*cut_by, (a + b) / 2, kStandardTable.jaws.liner)) continue;
      const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kCell)));
      for (int j = 0; j < pieces; ++j) {
        const Vec3 u = a + (b - a) * (static_cast<double>(j) / pieces),
                   v = a + (b - a) * (static_cast<double>(j + 1) / pieces);
        mesh.add_quad(u + Vec3(0, 0, z0), v + Vec3(0, 0, z0), v + Vec3(0, 0, z1), u + Vec3(0, 0, z1), color, kCell);
      }
    }
  }
}

std::vector<Vec3> circle_outline(const Vec3& centre, double radius, double z) {
  std::vector<Vec3> points;
  for (int k = 0; k < kHoleSegments; ++k) {
    const double a = 2 * std::numbers::pi * k / kHoleSegments;
    points.push_back(Vec3(centre.x() + radius * std::cos(a), centre.y() + radius * std::sin(a), z));
  }
  return points;
}

// The throat seen from above, grown by `grow`, at height z: a convex outline from one jaw's nose end
// along its facing, round the back, and along the other facing to the other nose end.
std::vector<Vec3> throat_outline(const PocketMouth& m, double grow, double z) {
  if (!m.jawed()) return circle_outline(m.centre, m.drop_radius + grow, z);
  const Vec3 lift(0, 0, z);
  std::vector<Vec3> points{m.nose[0] - grow * m.inward[0] + lift};
  const Vec3 t0 = m.tangent[0] - m.throat_centre, t1 = m.tangent[1] - m.throat_centre;
  const double a0 = std::atan2(t0.y(), t0.x()), back = std::atan2(m.axis.y(), m.axis.x());
  double sweep = std::remainder(std::atan2(t1.y(), t1.x()) - a0, 2 * std::numbers::pi);
  // Round the back: the way from the first tangent point that passes the axis.
  const double to_back = std::remainder(back - a0, 2 * std::numbers::pi);
  if ((to_back > 0) != (sweep > 0)) sweep += sweep > 0 ? -2 * std::numbers::pi : 2 * std::numbers::pi;
  const int steps = std::max(4, static_cast<int>(std::ceil(std::abs(sweep) / (2 * std::numbers::pi) * kHoleSegments)));
  const double r = m.throat_radius + grow;
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + sweep * k / steps;
    points.push_back(Vec3(m.throat_centre.x() + r * std::cos(a), m.throat_centre.y() + r * std::sin(a), z));
  }
  points.push_back(m.nose[1] - grow * m.inward[1] + lift);
  return points;
}

// The inside of a pocket: the leather liner along the throat (up to the wood's top where it runs
// through the wood, to the bed between the cushions' cloth-covered facings), the slate's edge round
// the drop circle, and the cup's floor; each wall piece inside the other shape is left out.
void add_pocket(MeshData& mesh, const PocketMouth& m, const Bounds& wood_inner, double top) {
  const auto inside_wood = [&](const Vec3& p) {
    return p.x() > wood_inner.x0 && p.x() < wood_inner.x1 && p.y() > wood_inner.y0 && p.y() < wood_inner.y1;
  };
  const auto walls = [&](const std::vector<Vec3>& outline, bool throat) {
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec3& p = outline[k];
      const Vec3& q = outline[(k + 1) % outline.size()];
      const Vec3 mid = (p + q) / 2;
      if (throat && m.jawed() && k + 1 == outline.size()) continue;  // the mouth: open
      // Below the bed only the outline of throat and drop circle together; above it the throat's
      // liner, where it runs through the wood. A piece is left out only when it lies well inside the
      // other shape: where the two outlines touch, both are drawn.
      constexpr double kWell = 0.001;  // m
      if (!throat && m.in_throat(p, -kWell) && m.in_throat(q, -kWell)) continue;
      const bool in_circle =
          (p - m.centre).norm() < m.drop_radius - kWell && (q - m.centre).norm() < m.drop_radius - kWell;
      const double low = throat && in_circle ? 0 : kCupFloor;
      const double high = throat && !inside_wood(mid) ? top : 0;
      if (high <= low) continue;
      mesh.add_quad(p + Vec3(0, 0, low), q + Vec3(0, 0, low), q + Vec3(0, 0, high), p + Vec3(0, 0, high),
                    leather_color());
    }
  };
  walls(throat_outline(m, 0, 0), true);
  // The liner's edge on the wood's top, between the throat and the wood's cut.
  const std::vector<Vec3> inner = throat_outline(m, 0, top), outer = throat_outline(m, kStandardTable.jaws.liner, top);
  for (std::size_t k = 0; k + 1 < inner.size() && k + 1 < outer.size(); ++k)
    if (!inside_wood((inner[k] + inner[k + 1]) / 2))
      mesh.add_quad(inner[k], inner[k + 1], outer[k + 1], outer[k], liner_color());
  walls(circle_outline(m.centre, m.drop_radius, 0), false);
  mesh.add_polygon(throat_outline(m, 0, kCupFloor), leather_color());
  mesh.add_polygon(circle_outline(m.centre, m.drop_radius, kCupFloor), leather_color());
}

/// Angles round `centre` from `from` through `sweep` (radians) in steps of at most a kHoleSegments-th of
/// a turn, with every angle where the circle of `radius` crosses a side of `box` added: a piece then
/// lies wholly inside the box or wholly outside it.
std::vector<double> arc_angles(const Vec3& centre, double radius, double from, double sweep, const Bounds& box) {
  const int steps = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) / (2 * std::numbers::pi) * kHoleSegments)));
  std::vector<double> angles;
  for (int k = 0; k <= steps; ++k) angles.push_back(from + sweep * k / steps);
  const auto add_crossing = [&](double a) {
    const double t = std::remainder(a - from, 2 * std::numbers::pi);
    const double along = sweep > 0 ? (t < 0 ? t + 2 * std::numbers::pi : t) : (t > 0 ? t - 2 * std::numbers::pi : t);
    if (std::abs(along) < std::abs(sweep)) angles.push_back(from + along);
  };
  for (double x : {box.x0, box.x1})
    if (std::abs(x - centre.x()) < radius)
      for (double sign : {1.0, -1.0}) add_crossing(sign * std::acos((x - centre.x()) / radius));
  for (double y : {box.y0, box.y1}) {
    if (std::abs(y - centre.y()) >= radius) continue;
    const double a = std::asin((y - centre.y()) / radius);
    add_crossing(a);
    add_crossing(std::numbers::pi - a);
  }
  std::sort(angles.begin(), angles.end());
  if (sweep < 0) std::reverse(angles.begin(), angles.end());
  return angles;
}

// A cut pocket's inside, the physics' own hole: on the shelf's side (from one facing's end round the
// front to the other's) the slate's edge rounded where the cloth wraps over it (lip_round), then the
// hole's wall down to the cup's floor; round the back, under the cushions' cut ends, the wall up to the
// bed, and where it runs through the wood the leather liner up to the wood's top, its edge there; the
// cup's floor, where the physics leaves a pocketed ball.
void add_cut_pocket(MeshData& mesh, const PocketMouth& m, const Bounds& wood_inner, double top) {
  const double r = m.drop_radius, lip = kStandardTable.jaws.lip_round, liner = kStandardTable.jaws.liner;
  const auto angle_of = [&](const Vec3& p) { return std::atan2(p.y() - m.centre.y(), p.x() - m.centre.x()); };
  const double a0 = angle_of(m.tangent[0]), back = std::atan2(m.axis.y(), m.axis.x());
  double sweep = std::remainder(angle_of(m.tangent[1]) - a0, 2 * std::numbers::pi);
  if ((std::remainder(back - a0, 2 * std::numbers::pi) > 0) != (sweep > 0))
    sweep += sweep > 0 ? -2 * std::numbers::pi : 2 * std::numbers::pi;
  const auto at = [&](double a, double radius, double z) {
    return Vec3(m.centre.x() + radius * std::cos(a), m.centre.y() + radius * std::sin(a), z);
  };
  const auto inside_wood = [&](const Vec3& p) {
    return p.x() > wood_inner.x0 && p.x() < wood_inner.x1 && p.y() > wood_inner.y0 && p.y() < wood_inner.y1;
  };
  // Round the back, from the first facing's end to the other's.
  const std::vector<double> rear = arc_angles(m.centre, r, a0, sweep, wood_inner);
  for (std::size_t k = 0; k + 1 < rear.size(); ++k) {
    const double u = rear[k], v = rear[k + 1];
    const bool wood = !inside_wood(at((u + v) / 2, r, 0));
    const double high = wood ? top : 0;
    mesh.add_quad(at(u, r, kCupFloor), at(v, r, kCupFloor), at(v, r, high), at(u, r, high), leather_color());
    if (wood) mesh.add_quad(at(u, r, top), at(v, r, top), at(v, r + liner, top), at(u, r + liner, top), liner_color());
  }
  // Round the front, under the shelf: the rounded lip, then the wall.
  const double front = sweep > 0 ? sweep - 2 * std::numbers::pi : sweep + 2 * std::numbers::pi;
  const std::vector<double> shelf = arc_angles(m.centre, r, a0, front, wood_inner);
  const Vec3 cloth = cloth_color() * 0.8;
  for (std::size_t k = 0; k + 1 < shelf.size(); ++k) {
    const double u = shelf[k], v = shelf[k + 1];
    for (int j = 0; j < kRoundSteps; ++j) {
      const double p = std::numbers::pi / 2 * j / kRoundSteps, q = std::numbers::pi / 2 * (j + 1) / kRoundSteps;
      const double rp = r + lip - lip * std::sin(p), rq = r + lip - lip * std::sin(q);
      const double zp = -lip + lip * std::cos(p), zq = -lip + lip * std::cos(q);
      mesh.add_quad(at(u, rp, zp), at(v, rp, zp), at(v, rq, zq), at(u, rq, zq), cloth);
    }
    mesh.add_quad(at(u, r, kCupFloor), at(v, r, kCupFloor), at(v, r, -lip), at(u, r, -lip), leather_color());
  }
  mesh.add_polygon(circle_outline(m.centre, r, kCupFloor), leather_color());
}

// A cut pocket in the table model: the bed cut at its hole (grown by the slate's rounded lip), so the
// bed goes on between the facings as the shelf; the wood's top cut by the hole and by the way between
// the facings to it, each grown by the liner and each convex (together they are not: the hole reaches
// past the facings behind their ends); its inside. A shelf reaching past the cushions into the wood is
// cloth there too (as POV-Ray's slate).
void add_cut_pocket_model(TableModel& model, const PocketMouth& m, const Bounds& inner, double top) {
  const double liner = kStandardTable.jaws.liner;
  model.bed_holes.add_polygon(circle_outline(m.centre, m.drop_radius + kStandardTable.jaws.lip_round, 0), hole_color());
  const Vec3 lift(0, 0, top);
  model.top_holes.add_polygon(circle_outline(m.centre, m.drop_radius + liner, top), hole_color());
  model.top_holes.add_polygon({m.nose[0] - liner * m.inward[0] + lift, m.tangent[0] - liner * m.inward[0] + lift,
                               m.tangent[1] - liner * m.inward[1] + lift, m.nose[1] - liner * m.inward[1] + lift},
                              hole_color());
  add_cut_pocket(model.pockets, m, inner, top);
  const std::vector<Vec3> shelf = {m.nose[0], m.tangent[0], m.tangent[1], m.nose[1]};
  if (std::any_of(shelf.begin(), shelf.end(), [&](const Vec3& p) {
        return p.x() < inner.x0 || p.x() > inner.x1 || p.y() < inner.y0 || p.y() > inner.y1;
      }))
    model.cloth.add_polygon(shelf, cloth_color());
}

// A bare pocket (a scene's own `pocket` line) in the table model: the bed cut at its drop circle and its
// throat, the wood's top at its throat grown by the liner, and its inside.
void add_bare_pocket_model(TableModel& model, const PocketMouth& m, const Bounds& inner, double top) {
  model.bed_holes.add_polygon(circle_outline(m.centre, m.drop_radius, 0), hole_color());
  model.bed_holes.add_polygon(throat_outline(m, 0, 0), hole_color());
  model.top_holes.add_polygon(throat_outline(m, kStandardTable.jaws.liner, top), hole_color());
  add_pocket(model.pockets, m, inner, top);
}

void add_sight(MeshData& mesh, const SightPlace& sight) {
  constexpr double kAboveWood = 0.0004;  // m, lifted off the wood's top so the two never fight in depth
  const double l = kStandardTable.sights.length / 2, w = kStandardTable.sights.width / 2;  // half-diagonals
  const Vec3 u = sight.along_x ? Vec3(l, 0, 0) : Vec3(0, l, 0);
  const Vec3 v = sight.along_x ? Vec3(0, w, 0) : Vec3(w, 0, 0);
  const Vec3 centre = sight.centre + Vec3(0, 0, kAboveWood);
  mesh.add_quad(centre - u, centre - v, centre + u, centre + v, sight_color());
}

}  // namespace

Vec3 cloth_color() { return srgb(20, 112, 62); }

TableModel build_table_model(const Scene& scene) {
  TableModel model;
  const TableLayout layout = table_layout(scene);
  const double top = layout.rail_top;
  model.top_height = top;

  const Bounds& inner = layout.wood_inner;
  const Bounds& outer = layout.wood_outer;

  model.cloth.add_quad(Vec3(inner.x0, inner.y0, 0), Vec3(inner.x1, inner.y0, 0), Vec3(inner.x1, inner.y1, 0),
                       Vec3(inner.x0, inner.y1, 0), cloth_color(), kCell);
  for (std::size_t i = 0; i < scene.rails.size(); ++i)
    add_cushion(model.body, scene.rails[i], layout.cushion_top, layout.ends_a[i], layout.ends_b[i], layout);

  add_frame_ring(model.tops, inner, outer, top, wood_color());
  add_walls(model.body, inner, 0, layout.cushion_top, liner_color(), &layout);
  add_walls(model.body, inner, layout.cushion_top, top, wood_color(), &layout);  // the wood's edge above the cushions
  add_walls(model.body, outer, kApronBottom, top, apron_color(), nullptr);
  model.body.add_quad(Vec3(outer.x0, outer.y0, kApronBottom), Vec3(outer.x1, outer.y0, kApronBottom),
                      Vec3(outer.x1, outer.y1, kApronBottom), Vec3(outer.x0, outer.y1, kApronBottom), apron_color());
  const double inset = 0.12;
  const double floor_z = -kStandardTable.bed_height;
  for (double x : {outer.x0 + inset, outer.x1 - inset - kLegSize})
    for (double y : {outer.y0 + inset, outer.y1 - inset - kLegSize})
      model.body.add_box(Vec3(x, y, floor_z), Vec3(x + kLegSize, y + kLegSize, kApronBottom), apron_color());
  const double floor = 6.0;
  model.body.add_quad(Vec3(-floor, -floor, floor_z), Vec3(floor, -floor, floor_z), Vec3(floor, floor, floor_z),
                      Vec3(-floor, floor, floor_z), srgb(52, 40, 32), kFloorCell);

  for (const SightPlace& sight : layout.sights) add_sight(model.tops, sight);

  for (const PocketMouth& m : layout.pockets) {
    if (m.cut)
      add_cut_pocket_model(model, m, inner, top);
    else
      add_bare_pocket_model(model, m, inner, top);
  }
  return model;
}

}  // namespace bsim
