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
constexpr double kJawSlope = 0.6;       // the cushion's end recedes this much per metre of depth
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
Vec3 pocket_color() { return srgb(16, 13, 12); }
Vec3 sight_color() { return srgb(236, 228, 206); }

using Bounds = TableRect;

void add_cushion(MeshData& body, MeshData& tops, const Rail& rail, double top) {
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
  // Each end recedes with depth so the jaw never reaches into the pocket mouth.
  const auto at = [&](const Vec3& end, double sign, const ProfilePoint& p) {
    return Vec3(end + out * p.offset + d * (sign * kJawSlope * p.offset) + Vec3(0, 0, p.height));
  };
  const Vec3 cloth = cloth_color() * 0.85;
  for (int k = 0; k + 1 < 4; ++k) {
    MeshData& target = k == 2 ? tops : body;
    target.add_quad(at(a, 1, profile[k]), at(b, -1, profile[k]), at(b, -1, profile[k + 1]), at(a, 1, profile[k + 1]),
                    cloth, kCell);
  }
  for (double sign : {1.0, -1.0}) {
    const Vec3& end = sign > 0 ? a : b;
    std::vector<Vec3> cap;
    for (const ProfilePoint& p : profile) cap.push_back(at(end, sign, p));
    cap.push_back(at(end, sign, {cushion.width, 0}));
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

bool inside_any_pocket(const Scene& scene, const Vec3& p) {
  for (const Pocket& pocket : scene.pockets)
    if (std::hypot(p.x() - pocket.center.x(), p.y() - pocket.center.y()) < pocket.radius) return true;
  return false;
}

// Vertical walls around a rectangle in pieces of kCell, leaving out the pieces inside a pocket.
void add_walls(MeshData& mesh, const Bounds& r, double z0, double z1, const Vec3& color, const Scene* cut_by) {
  const Vec3 c[4] = {{r.x0, r.y0, 0}, {r.x1, r.y0, 0}, {r.x1, r.y1, 0}, {r.x0, r.y1, 0}};
  for (int k = 0; k < 4; ++k) {
    const Vec3& p = c[k];
    const Vec3& q = c[(k + 1) % 4];
    const int pieces = std::max(1, static_cast<int>(std::ceil((q - p).norm() / kCell)));
    for (int i = 0; i < pieces; ++i) {
      const Vec3 a = p + (q - p) * (static_cast<double>(i) / pieces),
                 b = p + (q - p) * (static_cast<double>(i + 1) / pieces);
      if (cut_by && inside_any_pocket(*cut_by, (a + b) / 2)) continue;
      mesh.add_quad(a + Vec3(0, 0, z0), b + Vec3(0, 0, z0), b + Vec3(0, 0, z1), a + Vec3(0, 0, z1), color, kCell);
    }
  }
}

// The inside of a pocket: its wall below the bed all round, and up to the frame's top where the
// circle runs under the cushions and the frame (outside the playing area).
void add_pocket(MeshData& mesh, const Pocket& pocket, const Bounds& play, double top) {
  const Vec3 centre(pocket.center.x(), pocket.center.y(), 0);
  for (int k = 0; k < kHoleSegments; ++k) {
    const double a0 = 2 * std::numbers::pi * k / kHoleSegments, a1 = 2 * std::numbers::pi * (k + 1) / kHoleSegments;
    const Vec3 p = centre + pocket.radius * Vec3(std::cos(a0), std::sin(a0), 0);
    const Vec3 q = centre + pocket.radius * Vec3(std::cos(a1), std::sin(a1), 0);
    const Vec3 mid = (p + q) / 2;
    const bool under_frame = mid.x() < play.x0 || mid.x() > play.x1 || mid.y() < play.y0 || mid.y() > play.y1;
    const double high = under_frame ? top : 0;
    mesh.add_quad(p + Vec3(0, 0, -kPocketDepth), q + Vec3(0, 0, -kPocketDepth), q + Vec3(0, 0, high),
                  p + Vec3(0, 0, high), pocket_color());
  }
}

void add_disc(MeshData& mesh, const Vec3& centre, double radius, const Vec3& color) {
  std::vector<Vec3> points;
  for (int k = 0; k < kHoleSegments; ++k) {
    const double a = 2 * std::numbers::pi * k / kHoleSegments;
    points.push_back(centre + Vec3(radius * std::cos(a), radius * std::sin(a), 0));
  }
  mesh.add_polygon(points, color);
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

  const Bounds& play = layout.noses;
  const Bounds& inner = layout.wood_inner;
  const Bounds& outer = layout.wood_outer;

  model.cloth.add_quad(Vec3(inner.x0, inner.y0, 0), Vec3(inner.x1, inner.y0, 0), Vec3(inner.x1, inner.y1, 0),
                       Vec3(inner.x0, inner.y1, 0), cloth_color(), kCell);
  for (const Rail& r : scene.rails) add_cushion(model.body, model.tops, r, layout.cushion_top);

  add_frame_ring(model.tops, inner, outer, top, wood_color());
  add_walls(model.body, inner, 0, layout.cushion_top, liner_color(), &scene);
  add_walls(model.body, inner, layout.cushion_top, top, wood_color(), &scene);  // the wood's edge above the cushions
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

  for (const Pocket& p : scene.pockets) {
    add_disc(model.bed_holes, Vec3(p.center.x(), p.center.y(), 0), p.radius, hole_color());
    add_disc(model.top_holes, Vec3(p.center.x(), p.center.y(), top), p.radius, hole_color());
    add_disc(model.pockets, Vec3(p.center.x(), p.center.y(), -kPocketDepth), p.radius, hole_color());
    add_pocket(model.pockets, p, play, top);
  }
  return model;
}

}  // namespace bsim
