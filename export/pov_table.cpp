#include "pov_table.h"

#include <algorithm>
#include <string>
#include <vector>

#include "ball_look.h"
#include "pocket_fall.h"
#include "pov_format.h"
#include "table.h"

namespace bsim {

namespace {

struct Point2 {
  double x = 0, y = 0;
};

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Counter-clockwise convex hull (Andrew's monotone chain): the playing area inside the noses.
std::vector<Point2> convex_hull(std::vector<Point2> points) {
  std::sort(points.begin(), points.end(),
            [](const Point2& a, const Point2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end(),
                           [](const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }),
               points.end());
  if (points.size() < 3) return points;
  std::vector<Point2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

/// The direction a pocket opens away from the bed: the mean outward normal of the cushions that
/// end at it; a pocket no cushion ends at opens away from the table's middle, and is not stretched.
struct PocketOpening {
  Point2 out{1, 0};
  double stretch = 0;  ///< m the opening reaches back into the rail
};

PocketOpening pocket_opening(const Pocket& pocket, const std::vector<Rail>& rails, const Point2& middle) {
  constexpr double kNearEnd = 0.01;  // m beyond the pocket's radius that still counts as a jaw
  constexpr double kStretch = 0.45;  // of the radius: how far the cut reaches under the rail
  Vec3 sum(0, 0, 0);
  for (const Rail& rail : rails) {
    const Vec3 d = rail.b - rail.a;
    const Vec3 outward = Vec3(-d.y(), d.x(), 0).normalized();
    auto near = [&](const Vec3& p) {
      return (Vec3(p.x(), p.y(), 0) - Vec3(pocket.center.x(), pocket.center.y(), 0)).norm() <= pocket.radius + kNearEnd;
    };
    if (d.norm() > 1e-9 && (near(rail.a) || near(rail.b))) sum += outward;
  }
  if (sum.norm() > 1e-9) {
    sum.normalize();
    return {{sum.x(), sum.y()}, kStretch * pocket.radius};
  }
  const Point2 away{pocket.center.x() - middle.x, pocket.center.y() - middle.y};
  const double length = std::hypot(away.x, away.y);
  if (length < 1e-9) return {};
  return {{away.x / length, away.y / length}, 0.0};
}

template <class T, class F>
void write_array(std::ostream& out, const char* name, const std::vector<T>& items, F&& text) {
  out << "#declare " << name << " = array[" << items.size() << "] {";
  for (std::size_t i = 0; i < items.size(); ++i) out << (i ? ", " : " ") << text(items[i]);
  out << " }\n";
}

std::string pov_srgb(const SrgbColor& c) {
  return "<" + pov_number(c.r / 255.0) + ", " + pov_number(c.g / 255.0) + ", " + pov_number(c.b / 255.0) + ">";
}

/// The table description's numbers the models are built from: the same as the GL preview's.
void write_table_description(const TableLayout& layout, std::ostream& out) {
  const TableSpec& spec = kStandardTable;
  out << "\n// ---- from the table description (m)\n";
  out << "#declare CushionW = " << pov_number(spec.cushion.width) << ";  // the cushion's top, nose to the wood\n";
  out << "#declare CushionUndercut = " << pov_number(spec.cushion.undercut)
      << ";  // the cushion's foot on the bed, behind the nose\n";
  out << "#declare CushionTopZ = " << pov_number(layout.cushion_top)
      << ";  // the cushions' top where it meets the wood\n";
  out << "#declare RailW = " << pov_number(spec.rail.width) << ";  // width of the wooden rail's top\n";
  out << "#declare RailTopZ = " << pov_number(layout.rail_top) << ";  // the wood's top, a little above the noses\n";
  out << "#declare FloorZ = " << pov_number(-spec.bed_height) << ";\n";
  const LampSpec& lamp = kRoom.lamp;
  out << "#declare CeilingZ = " << pov_number(kRoom.ceiling) << ";\n";
  out << "#declare RoomMargin = " << pov_number(kRoom.margin) << ";  // from the table's outer edge to the walls\n";
  out << "#declare LampZ = " << pov_number(layout.lamp_bottom) << ";  // the lamp shade's rim\n";
  out << "#declare LampTopZ = " << pov_number(layout.lamp_top) << ";  // and its top\n";
  out << "#declare LampHalf = "
      << pov_vector2(0.5 * (layout.lamp.x1 - layout.lamp.x0), 0.5 * (layout.lamp.y1 - layout.lamp.y0))
      << ";  // half the shade seen from above, over Middle\n";
  out << "#declare LampWall = " << pov_number(lamp.wall) << ";\n";
  out << "#declare LampCordR = " << pov_number(lamp.cord_radius) << ";\n";
  out << "#declare SightLength = " << pov_number(spec.sights.length) << ";  // the diamond's diagonal along the rail\n";
  out << "#declare SightWidth = " << pov_number(spec.sights.width) << ";  // and across it\n";
  out << "#declare SightCount = " << layout.sights.size() << ";\n";
  if (!layout.sights.empty()) {
    write_array(out, "SightC", layout.sights,
                [](const SightPlace& s) { return pov_vector2(s.centre.x(), s.centre.y()); });
    write_array(out, "SightAlongX", layout.sights, [](const SightPlace& s) { return s.along_x ? "1" : "0"; });
  }
}

/// The standard ball colours, the same as the GL preview's. sRGB numbers, not colours: POV-Ray reads
/// `srgb` only after assumed_gamma, which the models set.
void write_ball_colours(std::ostream& out) {
  out << "\n// ---- the balls' colours (sRGB): 0 the cue ball's ivory, 1 to 8 solid, 9 to 15 striped on ivory\n";
  out << "#declare BallSrgb = array[16] {";
  for (int n = 0; n < 16; ++n) out << (n ? (n % 4 ? ", " : ",\n  ") : "\n  ") << pov_srgb(ball_srgb(n));
  out << "\n}\n";
}

}  // namespace

void write_pov_include(const Scene& scene, Quality quality, std::ostream& out, Look look) {
  out << "// Billiards Sim: the table, balls, cue stick, room and lights shared by every frame.\n"
         "// Units are metres, z is up, the bed is z = 0 and the table's middle is the origin.\n\n"
         "// ---- from the scene\n";
  out << "#declare Final = " << (quality == Quality::final ? 1 : 0)
      << ";  // area light (final) or point lights (draft)\n";
  out << "#declare BallR = " << pov_number(scene.physics.ball_radius) << ";\n";
  out << "#declare PocketDepth = " << pov_number(kPocketDepth) << ";  // how far below the bed a pocketed ball rests\n";

  std::vector<Point2> ends;
  for (const Rail& rail : scene.rails)
    for (const Vec3& p : {rail.a, rail.b}) ends.push_back({p.x(), p.y()});
  // Without cushions the layout is the standard bed: a bare bed around the pockets.
  const TableLayout layout = table_layout(scene);
  const TableRect& noses = layout.noses;
  const Point2 middle{(noses.x0 + noses.x1) / 2, (noses.y0 + noses.y1) / 2};

  out << "#declare NoseMin = " << pov_vector2(noses.x0, noses.y0) << ";\n";
  out << "#declare NoseMax = " << pov_vector2(noses.x1, noses.y1) << ";\n";
  out << "#declare RailCount = " << scene.rails.size() << ";\n";
  if (!scene.rails.empty()) {
    write_array(out, "RailA", scene.rails, [](const Rail& r) { return pov_vector2(r.a.x(), r.a.y()); });
    write_array(out, "RailB", scene.rails, [](const Rail& r) { return pov_vector2(r.b.x(), r.b.y()); });
    write_array(out, "RailH", scene.rails, [](const Rail& r) { return pov_number(r.a.z()); });
  }
  out << "#declare PocketCount = " << scene.pockets.size() << ";\n";
  if (!scene.pockets.empty()) {
    std::vector<PocketOpening> openings;
    for (const Pocket& p : scene.pockets) openings.push_back(pocket_opening(p, scene.rails, middle));
    write_array(out, "PocketC", scene.pockets, [](const Pocket& p) { return pov_vector2(p.center.x(), p.center.y()); });
    write_array(out, "PocketR", scene.pockets, [](const Pocket& p) { return pov_number(p.radius); });
    write_array(out, "PocketOut", openings, [](const PocketOpening& o) { return pov_vector2(o.out.x, o.out.y); });
    write_array(out, "PocketStretch", openings, [](const PocketOpening& o) { return pov_number(o.stretch); });
  }
  const std::vector<Point2> hull = convex_hull(ends);
  out << "#declare PlayHullCount = " << hull.size() << ";\n";
  if (hull.size() >= 3) {
    write_array(out, "PlayHull", hull, [](const Point2& p) { return pov_vector2(p.x, p.y); });
  }
  write_table_description(layout, out);
  write_ball_colours(out);
  out << "\n" << (look == Look::classic ? pov_classic_models_text() : pov_models_text());
}

}  // namespace bsim
