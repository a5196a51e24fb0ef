#include "table_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "table.h"

namespace bsim {

namespace {

// The cushion, the wood, the sights and the floor come from the table description (kStandardTable,
// table_layout); what follows is drawing detail.
constexpr double kNoseRound = 0.008;    // m outward from the nose where the profile reaches the cushion's top
constexpr double kSquareSlope = 0.6;    // a cushion end at no pocket recedes this much per metre of depth
constexpr double kApronBottom = -0.22;  // m
constexpr double kLegSize = 0.12;       // m
constexpr double kPocketDepth = 0.12;   // m below the bed
constexpr int kHoleSegments = 48;
constexpr double kCell = 0.06;       // m, tessellation of the table for its per-vertex lighting
constexpr double kFloorCell = 0.25;  // m

Vec3 wood_color() { return srgb(96, 42, 18); }
Vec3 apron_color() { return srgb(70, 30, 14); }
Vec3 liner_color() { return srgb(22, 18, 16); }
Vec3 hole_color() { return srgb(6, 6, 6); }
Vec3 pocket_color() { return srgb(17, 10, 6); }  // the near-black pocket leather, as POV-Ray's
Vec3 sight_color() { return srgb(236, 228, 206); }

using Bounds = TableRect;

// A cushion: its profile swept along the nose line; each end either cut along its jaw's facing (the
// facing runs on past the nose end by `slant` per metre behind the nose) or square, receding.
void add_cushion(MeshData& body, const Rail& rail, double top, const CushionEnd& end_a, const CushionEnd& end_b) {
  Vec3 d = rail.b - rail.a;
  d.z() = 0;
  const double length = d.norm();
  if (length < 1e-6) return;
  d /= length;
  const Vec3 out(-d.y(), d.x(), 0);  // the playing side is on the right of a -> b
  const double nose = rail.a.z();
  const Vec3 a(rail.a.x(), rail.a.y(), 0), b(rail.b.x(), rail.b.y(), 0);
  struct ProfilePoint {
    double offset, height;
  };
  const CushionProfile& cushion = kStandardTable.cushion;
  const ProfilePoint profile[] = {{cushion.undercut, 0}, {0, nose}, {kNoseRound, top}, {cushion.width, top}};
  // `away` points from the end past it (towards its pocket, if any).
  const auto at = [&](const Vec3& end, const Vec3& away, const CushionEnd& cut, const ProfilePoint& p) {
    const double slant = cut.pocket >= 0 ? cut.slant : -kSquareSlope;
    return Vec3(end + out * p.offset + away * (slant * p.offset) + Vec3(0, 0, p.height));
  };
  const Vec3 cloth = cloth_color() * 0.85;
  for (int k = 0; k + 1 < 4; ++k)
    body.add_quad(at(a, -d, end_a, profile[k]), at(b, d, end_b, profile[k]), at(b, d, end_b, profile[k + 1]),
                  at(a, -d, end_a, profile[k + 1]), cloth, kCell);
  for (bool at_a : {true, false}) {
    std::vector<Vec3> cap;
    for (const ProfilePoint& p : profile) cap.push_back(at_a ? at(a, -d, end_a, p) : at(b, d, end_b, p));
    cap.push_back(at_a ? at(a, -d, end_a, {cushion.width, 0}) : at(b, d, end_b, {cushion.width, 0}));
    body.add_polygon(cap, cloth);
  }
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

// Vertical walls around a rectangle in pieces of kCell, leaving out the pieces in a pocket's throat
// (grown by its liner).
void add_walls(MeshData& mesh, const Bounds& r, double z0, double z1, const Vec3& color, const TableLayout* cut_by) {
  const Vec3 c[4] = {{r.x0, r.y0, 0}, {r.x1, r.y0, 0}, {r.x1, r.y1, 0}, {r.x0, r.y1, 0}};
  for (int k = 0; k < 4; ++k) {
    const Vec3& p = c[k];
    const Vec3& q = c[(k + 1) % 4];
    const int pieces = std::max(1, static_cast<int>(std::ceil((q - p).norm() / kCell)));
    for (int i = 0; i < pieces; ++i) {
      const Vec3 a = p + (q - p) * (static_cast<double>(i) / pieces),
                 b = p + (q - p) * (static_cast<double>(i + 1) / pieces);
      if (cut_by && inside_any_throat(*cut_by, (a + b) / 2, kStandardTable.jaws.liner)) continue;
      mesh.add_quad(a + Vec3(0, 0, z0), b + Vec3(0, 0, z0), b + Vec3(0, 0, z1), a + Vec3(0, 0, z1), color, kCell);
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
      const double low = throat && in_circle ? 0 : -kPocketDepth;
      const double high = throat && !inside_wood(mid) ? top : 0;
      if (high <= low) continue;
      mesh.add_quad(p + Vec3(0, 0, low), q + Vec3(0, 0, low), q + Vec3(0, 0, high), p + Vec3(0, 0, high),
                    pocket_color());
    }
  };
  walls(throat_outline(m, 0, 0), true);
  // The liner's edge on the wood's top, between the throat and the wood's cut.
  const std::vector<Vec3> inner = throat_outline(m, 0, top), outer = throat_outline(m, kStandardTable.jaws.liner, top);
  for (std::size_t k = 0; k + 1 < inner.size() && k + 1 < outer.size(); ++k)
    if (!inside_wood((inner[k] + inner[k + 1]) / 2))
      mesh.add_quad(inner[k], inner[k + 1], outer[k + 1], outer[k], liner_color());
  walls(circle_outline(m.centre, m.drop_radius, 0), false);
  mesh.add_polygon(throat_outline(m, 0, -kPocketDepth), pocket_color());
  mesh.add_polygon(circle_outline(m.centre, m.drop_radius, -kPocketDepth), pocket_color());
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
    add_cushion(model.body, scene.rails[i], layout.cushion_top, layout.ends_a[i], layout.ends_b[i]);

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
    model.bed_holes.add_polygon(circle_outline(m.centre, m.drop_radius, 0), hole_color());
    model.bed_holes.add_polygon(throat_outline(m, 0, 0), hole_color());
    model.top_holes.add_polygon(throat_outline(m, kStandardTable.jaws.liner, top), hole_color());
    add_pocket(model.pockets, m, inner, top);
  }
  return model;
}

}  // namespace bsim
