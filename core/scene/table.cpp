#include "table.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "scene.h"

namespace bsim {

namespace {

/// One cushion end near a pocket: the nose end, the nose's direction into the pocket and the
/// cushion's outward normal (away from the bed).
struct JawEnd {
  int rail = -1;
  bool at_b = false;
  Vec3 nose{0, 0, 0};
  Vec3 along{1, 0, 0};
  Vec3 out{0, 1, 0};
  double distance = 0;  ///< m from the drop circle's centre
};

}  // namespace

Rail PocketMouth::facing_line(int i, double nose_height) const {
  const auto k = static_cast<std::size_t>(i);
  Rail face{
      Vec3(face_start[k].x(), face_start[k].y(), nose_height), Vec3(tangent[k].x(), tangent[k].y(), nose_height), {}};
  const Vec3 dir = face.b - face.a;
  if (Vec3(dir.y(), -dir.x(), 0).dot(inward[k]) < 0) std::swap(face.a, face.b);
  return face;
}

bool PocketMouth::in_throat(const Vec3& p, double grow) const {
  const Vec3 q = flat(p);
  if ((q - throat_centre).norm() <= throat_radius + grow) return true;
  if (!jawed()) return false;
  const Vec3 middle = (nose[0] + nose[1]) / 2;
  if ((q - middle).dot(axis) < -grow || (q - (tangent[0] + tangent[1]) / 2).dot(axis) > 0) return false;
  for (int i = 0; i < 2; ++i)
    if ((q - nose[i]).dot(inward[i]) < -grow) return false;
  return true;
}

namespace {

/// Every rail end as a jaw might use it, with its distance from `from`: its nose's direction into the
/// gap beyond it and the cushion's outward normal.
std::vector<JawEnd> rail_ends(const std::vector<Rail>& rails, const Vec3& from) {
  std::vector<JawEnd> ends;
  for (std::size_t i = 0; i < rails.size(); ++i) {
    const Vec3 d = flat(rails[i].b - rails[i].a);
    if (d.norm() < 1e-9) continue;
    const Vec3 along = d.normalized();
    const Vec3 out(-along.y(), along.x(), 0);  // the playing side is on the right of a -> b
    for (bool at_b : {false, true}) {
      const Vec3 nose = flat(at_b ? rails[i].b : rails[i].a);
      ends.push_back({static_cast<int>(i), at_b, nose, at_b ? along : Vec3(-along), out, (nose - flat(from)).norm()});
    }
  }
  return ends;
}

/// The rail end at plan point p (within round-off); none when no rail ends there.
std::optional<JawEnd> rail_end_at(const Vec3& p, const std::vector<Rail>& rails) {
  for (const JawEnd& e : rail_ends(rails, p))
    if (e.distance < 1e-9) return e;
  return std::nullopt;
}

/// A pocket as its drop circle alone, the throat the circle itself: where every mouth starts.
PocketMouth plain_mouth(const Pocket& pocket) {
  PocketMouth m;
  m.centre = flat(pocket.center);
  m.drop_radius = pocket.radius;
  m.throat_centre = m.centre;
  m.throat_radius = pocket.radius;
  return m;
}

/// A cut pocket: the jaws at its own jaw points, each rounded and faced at the WPA angle, the facings
/// running back to the hole. Bare (kind bare) when the rails do not end at its jaw points.
PocketMouth cut_mouth(const Pocket& pocket, const std::vector<Rail>& rails) {
  const PocketJaws& spec = kStandardTable.jaws;
  PocketMouth m = plain_mouth(pocket);
  std::optional<JawEnd> end[2] = {rail_end_at(pocket.jaw[0], rails), rail_end_at(pocket.jaw[1], rails)};
  if (!end[0] || !end[1]) return m;
  m.kind = pocket.kind;
  m.cut = true;
  m.facing_deg = m.kind == PocketKind::side ? spec.side_facing_deg : spec.corner_facing_deg;
  m.axis = flat(pocket.axis).normalized();
  m.round_radius = pocket.jaw_radius;
  const double turn = m.turn(), half = radians(m.facing_deg) / 2;
  const double tangent = m.round_radius / std::tan(half);  // from the jaw point to where the rounding ends
  for (int i = 0; i < 2; ++i) {
    const JawEnd& e = *end[i];
    m.rail[i] = e.rail;
    m.at_b[i] = e.at_b;
    m.nose[i] = e.nose;
    m.facing[i] = std::cos(turn) * e.along + std::sin(turn) * e.out;
    Vec3 normal(-m.facing[i].y(), m.facing[i].x(), 0);
    if (normal.dot(end[1 - i]->nose - e.nose) < 0) normal = -normal;  // towards the other jaw
    m.inward[i] = normal;
    // The rounding sits in the cushion, on the bisector of the facing angle between the nose (running
    // back from the pocket) and the facing.
    m.round_centre[i] = e.nose + m.round_radius / std::sin(half) * Vec3(m.facing[i] - e.along).normalized();
    m.nose_end[i] = e.nose - tangent * e.along;
    m.face_start[i] = e.nose + tangent * m.facing[i];
    // The facing runs back until it meets the hole's edge (or, should it pass the hole, abreast of it).
    const Vec3 to = m.centre - e.nose;
    const double along = to.dot(m.facing[i]), miss2 = to.squaredNorm() - along * along;
    const double r2 = m.drop_radius * m.drop_radius;
    const double reach = miss2 < r2 ? along - std::sqrt(r2 - miss2) : along;
    m.tangent[i] = e.nose + std::max(reach, 2 * tangent) * m.facing[i];
  }
  return m;
}

}  // namespace

PocketMouth pocket_mouth(const Pocket& pocket, const std::vector<Rail>& rails) {
  if (pocket.cut) return cut_mouth(pocket, rails);
  const PocketJaws& spec = kStandardTable.jaws;
  PocketMouth m = plain_mouth(pocket);

  // The cushion ends on or near the drop circle, nearest first: the two nearest are the jaws.
  std::vector<JawEnd> ends = rail_ends(rails, m.centre);
  std::erase_if(ends, [&](const JawEnd& e) { return e.distance > pocket.radius + spec.near_end; });
  std::stable_sort(ends.begin(), ends.end(), [](const JawEnd& a, const JawEnd& b) { return a.distance < b.distance; });
  if (ends.size() < 2) return m;
  const JawEnd& j0 = ends[0];
  const JawEnd& j1 = ends[1];
  if ((j1.nose - j0.nose).norm() < 1e-6) return m;

  // Collinear noses running at each other make a side pocket; noses meeting at an angle a corner.
  const double cos_side = std::cos(radians(spec.side_within_deg));
  m.kind = j0.along.dot(-j1.along) >= cos_side ? PocketKind::side : PocketKind::corner;
  m.facing_deg = m.kind == PocketKind::side ? spec.side_facing_deg : spec.corner_facing_deg;
  // The facing leaves the nose end turned from the nose's direction into the pocket by 180 degrees
  // less the facing angle, towards the cushion's back.
  const double turn = m.turn();
  const JawEnd* jaw[2] = {&j0, &j1};
  for (int i = 0; i < 2; ++i) {
    m.rail[i] = jaw[i]->rail;
    m.at_b[i] = jaw[i]->at_b;
    m.nose[i] = jaw[i]->nose;
    m.facing[i] = std::cos(turn) * jaw[i]->along + std::sin(turn) * jaw[i]->out;
  }
  const Vec3 middle = (m.nose[0] + m.nose[1]) / 2;
  m.axis = (j0.out + j1.out).normalized();
  for (int i = 0; i < 2; ++i) {
    Vec3 normal(-m.facing[i].y(), m.facing[i].x(), 0);
    if (normal.dot(middle - m.nose[i]) < 0) normal = -normal;
    m.inward[i] = normal;
  }

  // The throat's round back: a circle between the facings, tangent to them, whose back reaches as
  // far behind the mouth as the drop circle does (and at least a little past the cushion into the
  // wood), so the cup below holds every ball the physics drops.
  const double half = (m.nose[1] - m.nose[0]).norm() / 2;
  // How far each facing leans in towards the middle line, as it runs back (the mean of the two).
  double lean = 0;
  for (int i = 0; i < 2; ++i) {
    const Vec3 to_middle = middle - m.nose[i];
    const Vec3 lateral = to_middle - to_middle.dot(m.axis) * m.axis;
    if (lateral.norm() > 1e-9) lean += 0.5 * m.facing[i].dot(lateral.normalized());
  }
  const double closing = std::asin(std::clamp(lean, -0.99, 0.99));
  const double back =
      std::max((m.centre - middle).dot(m.axis) + pocket.radius, kStandardTable.cushion.width + 2 * spec.liner);
  double t = std::max(0.0, (back - half * std::cos(closing)) / (1 - std::sin(closing)));
  if (closing > 0) t = std::min(t, 0.8 * half / std::tan(closing));
  m.throat_radius = half * std::cos(closing) - t * std::sin(closing);
  m.throat_centre = middle + t * m.axis;
  for (int i = 0; i < 2; ++i) m.tangent[i] = m.nose[i] + (m.throat_centre - m.nose[i]).dot(m.facing[i]) * m.facing[i];
  return m;
}

TableLayout table_layout(const Scene& scene) {
  const TableSpec& spec = kStandardTable;
  TableLayout layout;
  layout.noses = {-spec.half_length, -spec.half_width, spec.half_length, spec.half_width};
  layout.nose_height = spec.nose_height;
  if (!scene.rails.empty()) {
    const Vec3& first = scene.rails.front().a;
    layout.noses = {first.x(), first.y(), first.x(), first.y()};
    layout.nose_height = 0;
    for (const Rail& rail : scene.rails) {
      for (const Vec3& p : {rail.a, rail.b}) {
        layout.noses = {std::min(layout.noses.x0, p.x()), std::min(layout.noses.y0, p.y()),
                        std::max(layout.noses.x1, p.x()), std::max(layout.noses.y1, p.y())};
        layout.nose_height = std::max(layout.nose_height, p.z());
      }
    }
  }
  layout.wood_inner = layout.noses.grown(spec.cushion.width);
  layout.wood_outer = layout.wood_inner.grown(spec.rail.width);
  layout.cushion_top = layout.nose_height + spec.cushion.top_rise;
  layout.rail_top = layout.nose_height + spec.rail.top_rise;
  layout.floor = -spec.bed_height;

  const LampSpec& lamp = kRoom.lamp;
  const double middle_x = 0.5 * (layout.noses.x0 + layout.noses.x1);
  const double middle_y = 0.5 * (layout.noses.y0 + layout.noses.y1);
  const double half_length = std::max(lamp.min_half_length, lamp.length_share * (layout.noses.x1 - layout.noses.x0));
  layout.lamp = {middle_x - half_length, middle_y - lamp.half_width, middle_x + half_length,
                 middle_y + lamp.half_width};
  layout.lamp_bottom = lamp.bottom;
  layout.lamp_top = lamp.bottom + lamp.height;

  const TableRect& n = layout.noses;
  const double d = spec.sights.from_nose, z = layout.rail_top;
  for (int i = 1; i < spec.sights.long_spaces; ++i) {
    if (2 * i == spec.sights.long_spaces) continue;  // the side pocket
    const double x = n.x0 + (n.x1 - n.x0) * i / spec.sights.long_spaces;
    layout.sights.push_back({Vec3(x, n.y0 - d, z), true});
    layout.sights.push_back({Vec3(x, n.y1 + d, z), true});
  }
  for (int i = 1; i < spec.sights.short_spaces; ++i) {
    const double y = n.y0 + (n.y1 - n.y0) * i / spec.sights.short_spaces;
    layout.sights.push_back({Vec3(n.x0 - d, y, z), false});
    layout.sights.push_back({Vec3(n.x1 + d, y, z), false});
  }
  layout.ends_a.assign(scene.rails.size(), {});
  layout.ends_b.assign(scene.rails.size(), {});
  for (std::size_t k = 0; k < scene.pockets.size(); ++k) {
    const PocketMouth m = pocket_mouth(scene.pockets[k], scene.rails);
    for (int i = 0; m.jawed() && i < 2; ++i) {
      CushionEnd& end = (m.at_b[i] ? layout.ends_b : layout.ends_a)[static_cast<std::size_t>(m.rail[i])];
      end.pocket = static_cast<int>(k);
      end.slant = 1 / std::tan(m.turn());
    }
    layout.pockets.push_back(m);
  }
  return layout;
}

}  // namespace bsim
