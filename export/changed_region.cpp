#include "changed_region.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "pocket_fall.h"
#include "pov_table.h"
#include "scene.h"
#include "table.h"

namespace bsim {

namespace {

/// m: a shadow caster reaching within this of the lamp's light is not bounded (the frame is rendered
/// whole).
constexpr double kNearest = 0.01;

/// Spheres whose convex hull must be kept in the region.
using Hull = std::vector<BoundSphere>;

/// How far beyond `casts`, as a factor on the way from a light point, a point the lamp lights can lie
/// (infinity: no bound). The lamp's colour and cone are taken on the ray to its centre, so a point P
/// it lights lies within the falloff angle of straight down from there, and so within
/// tan(falloff) (Lz - P.z) of the light's rectangle seen from above. A point P = L + t (X - L) beyond
/// a point X of the casts from a light point L lies at least t d - diag from that rectangle (d: the
/// casts' least distance from it seen from above, diag: its diagonal) and t (Lz - bottom) below the
/// light at most: lit only while t (d - tan(falloff) (Lz - bottom)) <= diag.
double cone_scale(const std::vector<BoundSphere>& casts, const RegionScene& scene) {
  double d = 1e300, bottom = 1e300;
  for (const BoundSphere& s : casts) {
    const double dx = std::max({scene.light_x0 - s.centre.x(), s.centre.x() - scene.light_x1, 0.0});
    const double dy = std::max({scene.light_y0 - s.centre.y(), s.centre.y() - scene.light_y1, 0.0});
    d = std::min(d, std::hypot(dx, dy) - s.radius);
    bottom = std::min(bottom, s.centre.z() - s.radius);
  }
  const double k = d - std::tan(scene.cone_deg * std::numbers::pi / 180) * (scene.light_z - bottom);
  if (k <= 1e-9) return std::numeric_limits<double>::infinity();
  return std::hypot(scene.light_x1 - scene.light_x0, scene.light_y1 - scene.light_y0) / k;
}

/// The hull of the shadow `casts` throws from the lamp down to `z0`, or less far where the lamp's
/// cone ends (see changed_region.h); false when a sphere reaches up to the light outside that bound.
bool shadow_hull(const std::vector<BoundSphere>& casts, const RegionScene& scene, double z0, Hull& hull) {
  double scale = 1;
  bool to_light = false;
  for (const BoundSphere& s : casts) {
    const double top = s.centre.z() + s.radius;
    if (top > scene.light_z - kNearest)
      to_light = true;
    else
      scale = std::max(scale, (scene.light_z - z0) / (scene.light_z - top));
  }
  const double cone = cone_scale(casts, scene);
  if (to_light && !std::isfinite(cone)) return false;
  scale = std::max(1.0, to_light ? cone : std::min(scale, cone));
  hull = casts;
  for (double lx : {scene.light_x0, scene.light_x1}) {
    for (double ly : {scene.light_y0, scene.light_y1}) {
      const Vec3 light(lx, ly, scene.light_z);
      for (const BoundSphere& s : casts) hull.push_back({light + scale * (s.centre - light), scale * s.radius});
    }
  }
  return true;
}

/// An upright box as a hull: its eight corners (two spheres round them would hold more).
Hull box_hull(const Vec3& min, const Vec3& max) {
  Hull hull;
  for (int corner = 0; corner < 8; ++corner)
    hull.push_back(
        {Vec3(corner & 1 ? max.x() : min.x(), corner & 2 ? max.y() : min.y(), corner & 4 ? max.z() : min.z()), 0.0});
  return hull;
}

/// The hull's extent seen from above.
struct PlanBox {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
};

PlanBox plan_box(const Hull& hull) {
  PlanBox box;
  for (const BoundSphere& s : hull) {
    box.x0 = std::min(box.x0, s.centre.x() - s.radius), box.x1 = std::max(box.x1, s.centre.x() + s.radius);
    box.y0 = std::min(box.y0, s.centre.y() - s.radius), box.y1 = std::max(box.y1, s.centre.y() + s.radius);
  }
  return box;
}

/// Whether the hull stays over the table's wooden frame (seen from above).
bool over_frame(const Hull& hull, const RegionScene& scene) {
  const PlanBox box = plan_box(hull);
  return box.x0 >= scene.frame_x0 && box.x1 <= scene.frame_x1 && box.y0 >= scene.frame_y0 && box.y1 <= scene.frame_y1;
}

/// Whether a hull of extent `box` seen from above may reach pocket `p`'s opening.
bool reaches(const PlanBox& box, const RegionScene::Opening& p) {
  const double dx = std::max({box.x0 - p.x, p.x - box.x1, 0.0}), dy = std::max({box.y0 - p.y, p.y - box.y1, 0.0});
  return dx * dx + dy * dy <= p.radius * p.radius;
}

bool near_pocket(const Hull& hull, const RegionScene& scene) {
  const PlanBox box = plan_box(hull);
  return std::any_of(scene.pockets.begin(), scene.pockets.end(),
                     [&](const RegionScene::Opening& p) { return reaches(box, p); });
}

/// The capsule cut along its length into pieces of at most kPieceLength, each the hull of two
/// spheres between its ends: together they are the capsule, and each piece's picture and shadow are
/// far smaller than the whole one's box when the capsule is long (the stick lying across the picture).
std::vector<Hull> capsule_pieces(const BoundCapsule& c) {
  const double length = (c.b.centre - c.a.centre).norm();
  const int n = std::clamp(static_cast<int>(std::ceil(length / kPieceLength)), 1, kMostPieces);
  const auto at = [&](int k) {
    const double u = static_cast<double>(k) / n;
    return BoundSphere{c.a.centre + u * (c.b.centre - c.a.centre), c.a.radius + u * (c.b.radius - c.a.radius)};
  };
  std::vector<Hull> pieces;
  for (int k = 0; k < n; ++k) pieces.push_back({at(k), at(k + 1)});
  return pieces;
}

/// Where the shadow of one piece can fall, as hulls added to `hulls`; false when it cannot be bounded.
/// The lamp's light goes below the cloth only through a pocket's opening (into its cup) or beyond the
/// table's frame; when nothing it lights lies beyond the frame below the cloth (the room outside its
/// cone), the shadow down to the cloth and the lit inside of every cup it reaches hold it all.
bool piece_shadow(const Hull& piece, const RegionScene& scene, std::vector<Hull>& hulls) {
  // Wholly above the lamp's light it casts nothing: the lamp lights only what lies below it (its cone
  // points down), so every shadow ray runs below the light's plane.
  if (std::all_of(piece.begin(), piece.end(),
                  [&](const BoundSphere& s) { return s.centre.z() - s.radius > scene.light_z + kNearest; }))
    return true;
  Hull hull;
  if (!shadow_hull(piece, scene, scene.bed, hull)) return false;
  if (!scene.lamp_lights_room) {
    const PlanBox box = plan_box(hull);
    for (std::size_t p = 0; p < scene.pockets.size(); ++p)
      if (reaches(box, scene.pockets[p])) hulls.push_back(scene.cups[p]);
    hulls.push_back(std::move(hull));
    return true;
  }
  // Else down to the cups' floor when that stays over the frame, else to the room's floor.
  const bool on_cloth = over_frame(hull, scene) && !near_pocket(hull, scene);
  if (!on_cloth && !shadow_hull(piece, scene, scene.cup_floor, hull)) return false;
  if (!on_cloth && !over_frame(hull, scene) && !shadow_hull(piece, scene, scene.floor, hull)) return false;
  hulls.push_back(std::move(hull));
  return true;
}

/// The camera's projection onto a width x height picture, in pixels from its top-left corner.
class PixelProjection {
 public:
  PixelProjection(const CameraPose& pose, int width, int height)
      : view_(pose, kCameraFovDeg, static_cast<double>(width) / height), width_(width), height_(height) {}

  /// The hull's bounding rectangle in the picture, grown by the margin, snapped to the grid
  /// and clipped to the picture (empty when the hull is not in it). A hull reaching behind the camera's
  /// plane goes off the picture's edge on each side towards which it crosses that plane.
  PixelRect bound(const Hull& hull) const {
    std::vector<Vec3> front, behind;  // the corners of the spheres' boxes, from the eye in the view's axes
    for (const BoundSphere& s : hull) {
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 d =
            s.centre + s.radius * Vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1) - view_.eye();
        const Vec3 v(d.dot(view_.right()), d.dot(view_.up()), d.dot(view_.forward()));
        (v.z() > kAhead ? front : behind).push_back(v);
      }
    }
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec3& v : front) {
      const double x = 0.5 * width_ * (1 + v.x() / (v.z() * view_.half_width()));
      const double y = 0.5 * height_ * (1 - v.y() / (v.z() * view_.half_height()));
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    // Where an edge from a corner in front to one behind crosses the camera's plane, the hull's picture
    // runs off to infinity in the direction of that crossing point.
    for (const Vec3& f : front) {
      for (const Vec3& b : behind) {
        const Vec3 c = f + (f.z() / (f.z() - b.z())) * (b - f);
        if (c.x() > 0) x1 = 1e300;
        if (c.x() < 0) x0 = -1e300;
        if (c.y() > 0) y0 = -1e300;
        if (c.y() < 0) y1 = 1e300;
      }
    }
    if (front.empty() || x1 < -kRegionMarginPixels || y1 < -kRegionMarginPixels || x0 > width_ + kRegionMarginPixels ||
        y0 > height_ + kRegionMarginPixels)
      return {};
    return {snap_down(x0), snap_down(y0), snap_up(x1, width_), snap_up(y1, height_)};
  }

 private:
  /// m ahead of the eye a corner must lie to be projected; nearer ones count as crossing its plane.
  static constexpr double kAhead = 1e-6;

  static int snap_down(double v) {
    const double grown = std::clamp(std::floor(v) - kRegionMarginPixels, 0.0, 1e9);
    return static_cast<int>(grown) / kRegionGrid * kRegionGrid;
  }
  static int snap_up(double v, int limit) {
    const double grown = std::clamp(std::ceil(v) + kRegionMarginPixels, 0.0, static_cast<double>(limit));
    const int blocks = (static_cast<int>(grown) + kRegionGrid - 1) / kRegionGrid;
    return std::min(limit, blocks * kRegionGrid);
  }

  CameraView view_;
  int width_, height_;
};

PixelRect round_both(const PixelRect& a, const PixelRect& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

bool holds(const PixelRect& outer, const PixelRect& inner) {
  return outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && outer.x1 >= inner.x1 && outer.y1 >= inner.y1;
}

/// The grid's cells that the rectangles (on the grid, or ending at the picture's edge) cover, as
/// rectangles that do not overlap: each row's runs of covered cells, a run of the same columns as one
/// in the row above joined to it. Overlapping rectangles would trace their common pixels twice.
std::vector<PixelRect> disjoint_cover(const std::vector<PixelRect>& rects) {
  int right = 0, bottom = 0;
  for (const PixelRect& r : rects) right = std::max(right, r.x1), bottom = std::max(bottom, r.y1);
  const int columns = (right + kRegionGrid - 1) / kRegionGrid, rows = (bottom + kRegionGrid - 1) / kRegionGrid;
  std::vector<char> covered(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);
  const auto cell = [&](int x, int y) -> char& {
    return covered[static_cast<std::size_t>(y) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(x)];
  };
  for (const PixelRect& r : rects)
    for (int y = r.y0 / kRegionGrid; y * kRegionGrid < r.y1; ++y)
      for (int x = r.x0 / kRegionGrid; x * kRegionGrid < r.x1; ++x) cell(x, y) = 1;
  std::vector<PixelRect> cover;
  std::vector<std::size_t> above(static_cast<std::size_t>(columns), SIZE_MAX);  // the run starting there, last row
  for (int y = 0; y < rows; ++y) {
    std::vector<std::size_t> here(static_cast<std::size_t>(columns), SIZE_MAX);
    const int y0 = y * kRegionGrid, y1 = std::min(bottom, y0 + kRegionGrid);
    for (int x = 0; x < columns;) {
      if (!cell(x, y)) {
        ++x;
        continue;
      }
      int end = x;
      while (end < columns && cell(end, y)) ++end;
      const int x0 = x * kRegionGrid, x1 = std::min(right, end * kRegionGrid);
      const std::size_t joined = above[static_cast<std::size_t>(x)];
      if (joined != SIZE_MAX && cover[joined].x1 == x1 && cover[joined].y1 == y0) {
        cover[joined].y1 = y1;
        here[static_cast<std::size_t>(x)] = joined;
      } else {
        here[static_cast<std::size_t>(x)] = cover.size();
        cover.push_back({x0, y0, x1, y1});
      }
      x = end;
    }
    above = std::move(here);
  }
  return cover;
}

/// The hulls a changed part adds in one of the two frames: what is seen of it and its shadow, piece
/// by piece; false when its shadow cannot be bounded.
bool changed_hulls(const FramePart& part, const RegionScene& scene, std::vector<Hull>& hulls) {
  for (const BoundCapsule& c : part.seen)
    for (Hull& piece : capsule_pieces(c)) hulls.push_back(std::move(piece));
  for (const BoundCapsule& c : part.casts)
    for (const Hull& piece : capsule_pieces(c))
      if (!piece_shadow(piece, scene, hulls)) return false;
  return true;
}

PixelRect overlap_of(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

/// Where the shade's lacquer can show what changed (every hull in `hulls`, the balls that mirror it
/// included), added to `rects`. Each outer face is a plane mirror: a point X in front of it is seen
/// in it along the line from the eye to X mirrored in its plane, so within that image's picture and
/// within the shade's. A face the eye is behind shows nothing, and one whose normal points up (every
/// outer face) turns a ray from below up again: only an eye above the rim sees the table in it.
void add_shade_mirror(const Vec3& eye, const std::vector<Hull>& hulls, const RegionScene& scene,
                      const PixelProjection& projection, std::vector<PixelRect>& rects) {
  if (eye.z() < scene.shade_min.z()) return;
  const PixelRect shade = projection.bound(box_hull(scene.shade_min, scene.shade_max));
  if (shade.area() <= 0) return;
  for (const RegionScene::Mirror& face : scene.shade_faces) {
    if ((eye - face.point).dot(face.normal) <= 0) continue;
    for (const Hull& hull : hulls) {
      Hull image;
      for (const BoundSphere& s : hull) {
        const double ahead = (s.centre - face.point).dot(face.normal);
        if (ahead + s.radius > 0) image.push_back({s.centre - 2 * ahead * face.normal, s.radius});
      }
      if (image.empty()) continue;
      const PixelRect seen = overlap_of(projection.bound(image), shade);
      if (seen.x1 > seen.x0 && seen.y1 > seen.y0) rects.push_back(seen);
    }
  }
}

/// The outer faces of the lamp's shade as the include's ShadeSolid builds them: four sides drawn in
/// by the taper from the rim to the eaves, and the hipped roof's four faces from the eaves up to the
/// ridge at the shade's top.
std::vector<RegionScene::Mirror> shade_faces(const TableLayout& layout) {
  const LampSpec& lamp = kRoom.lamp;
  const double mx = 0.5 * (layout.lamp.x0 + layout.lamp.x1), my = 0.5 * (layout.lamp.y0 + layout.lamp.y1);
  const double hu = 0.5 * (layout.lamp.x1 - layout.lamp.x0), hv = 0.5 * (layout.lamp.y1 - layout.lamp.y0);
  const double rim = layout.lamp_bottom, pitch = lamp.roof_pitch_deg * std::numbers::pi / 180;
  const double eaves = layout.lamp_top - (hv - lamp.taper) * std::tan(pitch);
  std::vector<RegionScene::Mirror> faces;
  for (const double side : {1.0, -1.0}) {
    faces.push_back({Vec3(0, side * (eaves - rim), lamp.taper).normalized(), Vec3(mx, my + side * hv, rim)});
    faces.push_back({Vec3(side * (eaves - rim), 0, lamp.taper).normalized(), Vec3(mx + side * hu, my, rim)});
    faces.push_back({Vec3(0, side * std::sin(pitch), std::cos(pitch)), Vec3(mx, my + side * (hv - lamp.taper), eaves)});
    faces.push_back({Vec3(side * std::sin(pitch), 0, std::cos(pitch)), Vec3(mx + side * (hu - lamp.taper), my, eaves)});
  }
  return faces;
}

/// A sphere round the hull (round its box's middle).
BoundSphere enclosing(const Hull& hull) {
  Vec3 lo = hull.front().centre, hi = lo;
  for (const BoundSphere& s : hull) lo = lo.cwiseMin(s.centre), hi = hi.cwiseMax(s.centre);
  const Vec3 middle = 0.5 * (lo + hi);
  double radius = 0;
  for (const BoundSphere& s : hull) radius = std::max(radius, (s.centre - middle).norm() + s.radius);
  return {middle, radius};
}

/// How many mirrors in a row POV-Ray follows a ray through: the include's max_trace_level less the ray
/// from the eye (kMostReflections when it does not say).
int reflections_traced() {
  const std::string_view models = pov_models_text();
  const std::string_view key = "max_trace_level";
  const std::size_t at = models.find(key);
  if (at == std::string_view::npos) return kMostReflections;
  int level = 0;
  for (std::size_t i = at + key.size();
       i < models.size() && (models[i] == ' ' || std::isdigit(static_cast<unsigned char>(models[i]))); ++i)
    if (models[i] != ' ') level = 10 * level + (models[i] - '0');
  return level > 0 ? level - 1 : kMostReflections;
}

/// What the clear coat of each ball that stays as it was can show of the change: for every hull that
/// changed (and, when rays are followed through two mirrors or more, for every other ball and for the
/// lamp shade when a changed hull reaches up to it: a ray from a ball below the shade's rim turns up
/// off its faces, so it meets only what lies above the rim), the patch of the ball where a ray from
/// the eye can turn towards it. A ball reaching up to the shade counts whole.
void add_mirror_patches(const std::vector<BoundCapsule>& still_parts, const Vec3& eye, const RegionScene& scene,
                        std::vector<Hull>& hulls) {
  std::vector<BoundSphere> targets;
  bool reaches_shade = false;
  for (const Hull& hull : hulls) {
    targets.push_back(enclosing(hull));
    for (const BoundSphere& s : hull) reaches_shade = reaches_shade || s.centre.z() + s.radius >= scene.shade_min.z();
  }
  std::vector<BoundSphere> still;  // the balls that stay as they were
  for (const BoundCapsule& c : still_parts) still.push_back(enclosing({c.a, c.b}));
  const std::size_t changed = targets.size();
  if (scene.reflections >= 2) {
    targets.insert(targets.end(), still.begin(), still.end());
    if (reaches_shade) targets.push_back(enclosing(box_hull(scene.shade_min, scene.shade_max)));
  }
  for (std::size_t b = 0; b < still.size(); ++b) {
    const BoundSphere& ball = still[b];
    if (ball.centre.z() + ball.radius >= scene.shade_min.z()) {
      hulls.push_back({ball});
      continue;
    }
    for (std::size_t t = 0; t < targets.size(); ++t)
      if (t != changed + b) hulls.push_back({mirror_patch(ball, eye, targets[t])});
  }
}

}  // namespace

BoundSphere mirror_patch(const BoundSphere& ball, const Vec3& eye, const BoundSphere& target) {
  const BoundSphere& whole = ball;
  const Vec3 to_eye = eye - ball.centre, to_target = target.centre - ball.centre;
  const double eye_distance = to_eye.norm(), target_distance = to_target.norm();
  if (eye_distance <= ball.radius || target_distance <= ball.radius + target.radius) return whole;
  // The ways from a point of the ball to the eye and to a point of the target, each within a cone
  // round the way from the centre; as unit vectors, within these chords of the axes.
  const double to_eye_cone = std::asin(ball.radius / eye_distance);
  const double to_target_cone = std::asin((ball.radius + target.radius) / target_distance);
  const double chords = 2 * std::sin(to_eye_cone / 2) + 2 * std::sin(to_target_cone / 2);
  // The normal is along the sum of the two unit vectors, which lies within `chords` of the axes' sum.
  const Vec3 axes = to_eye / eye_distance + to_target / target_distance;
  const double sine = chords / axes.norm();  // of the cone's half-angle round the axes' sum
  if (ball.radius * sine + kBoundSlack >= ball.radius) return whole;
  const double cosine = std::sqrt(1 - sine * sine);
  // The cap of the bound's sphere within that cone lies in this sphere; the ball's own surface lies
  // within kBoundSlack inside the bound's (and its patch within kBoundSlack of the bound's cap).
  return {ball.centre + ball.radius * cosine * axes.normalized(), ball.radius * sine + kBoundSlack};
}

RegionScene region_scene(const Scene& scene) {
  const TableLayout layout = table_layout(scene);
  RegionScene r;
  // The include's lamp: its light (an area light, or two points in it for draft) 1 cm over the shade's
  // rim, inside the shade seen from above.
  r.light_x0 = layout.lamp.x0, r.light_y0 = layout.lamp.y0, r.light_x1 = layout.lamp.x1, r.light_y1 = layout.lamp.y1;
  r.light_z = layout.lamp_bottom + 0.01;
  r.cone_deg = kRoom.lamp.falloff_deg;
  r.shade_min = Vec3(layout.lamp.x0 - 0.01, layout.lamp.y0 - 0.01, layout.lamp_bottom - 0.01);
  r.shade_max = Vec3(layout.lamp.x1 + 0.01, layout.lamp.y1 + 0.01, layout.lamp_top + 0.01);
  r.shade_faces = shade_faces(layout);
  r.frame_x0 = layout.wood_outer.x0, r.frame_y0 = layout.wood_outer.y0;
  r.frame_x1 = layout.wood_outer.x1, r.frame_y1 = layout.wood_outer.y1;
  r.bed = -0.001;                      // the cloth's top is z = 0
  r.cup_floor = -kPocketDepth - 0.02;  // the cup's floor and its leather, with room to spare
  r.floor = layout.floor - 0.01;
  // Where the lamp's light goes down through each pocket, and its cup below. A cut pocket's shelf is
  // cloth like the bed, so only its hole in the slate opens (with the slate's rounded lip); the cup
  // under it (the include's PocketLiner) lies within the hole and its liner. Any other pocket opens
  // through its drop circle, its throat and its jaws, as the include's PocketBox, and its cup is
  // that opening carried down. All the lamp lights below the cloth through an opening lies in the
  // upright box round its cup's disc.
  const PocketJaws& jaws = kStandardTable.jaws;
  for (const PocketMouth& p : layout.pockets) {
    double radius = std::max(p.drop_radius, (p.throat_centre - p.centre).norm() + p.throat_radius);
    if (p.jawed()) radius = std::max({radius, (p.nose[0] - p.centre).norm(), (p.nose[1] - p.centre).norm()});
    const double opening = p.cut ? p.drop_radius + jaws.lip_round + 0.01 : radius + 0.02;
    const double cup = p.cut ? p.drop_radius + jaws.liner + 0.01 : opening;
    r.pockets.push_back({p.centre.x(), p.centre.y(), opening});
    r.cups.push_back(box_hull(Vec3(p.centre.x() - cup, p.centre.y() - cup, r.cup_floor),
                              Vec3(p.centre.x() + cup, p.centre.y() + cup, r.bed)));
  }
  // Beyond the frame and below the cloth the lamp lights nothing when the walls (and what hangs on
  // them, within kWallDepth of them) lie outside its cone, seen from the nearest point of its light:
  // the floor is lit by the room's fills alone (room.inc), the frame's outer faces look away from
  // the lamp and the table's body is under its top.
  const double reach = std::tan(kRoom.lamp.falloff_deg * std::numbers::pi / 180) * (r.light_z - r.floor);
  const double to_wall =
      std::min({r.light_x0 - (layout.wood_outer.x0 - kRoom.margin), (layout.wood_outer.x1 + kRoom.margin) - r.light_x1,
                r.light_y0 - (layout.wood_outer.y0 - kRoom.margin),
                (layout.wood_outer.y1 + kRoom.margin) - r.light_y1}) -
      kWallDepth;
  r.lamp_lights_room = to_wall <= reach;
  r.reflections = reflections_traced();
  return r;
}

std::vector<PixelRect> merge_regions(std::vector<PixelRect> rects) {
  std::erase_if(rects, [](const PixelRect& r) { return r.area() <= 0; });
  rects = disjoint_cover(rects);
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < rects.size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < rects.size() && !merged; ++j) {
        const PixelRect both = round_both(rects[i], rects[j]);
        if (both.area() > rects[i].area() + rects[j].area() + kRegionStartPixels) continue;
        std::erase_if(rects, [&](const PixelRect& r) { return holds(both, r); });
        rects.push_back(both);
        merged = true;
      }
    }
  }
  std::sort(rects.begin(), rects.end(),
            [](const PixelRect& a, const PixelRect& b) { return a.y0 != b.y0 ? a.y0 < b.y0 : a.x0 < b.x0; });
  return rects;
}

std::optional<std::vector<PixelRect>> changed_region(const FrameContent& reference, const FrameContent& frame,
                                                     const RegionScene& scene, int width, int height) {
  if (reference.camera != frame.camera || reference.parts.size() != frame.parts.size()) return std::nullopt;
  std::vector<Hull> hulls;
  bool changed = false;
  for (std::size_t i = 0; i < frame.parts.size(); ++i) {
    if (reference.parts[i].text == frame.parts[i].text) continue;
    changed = true;
    if (!changed_hulls(reference.parts[i], scene, hulls) || !changed_hulls(frame.parts[i], scene, hulls))
      return std::nullopt;
  }
  if (!changed) return std::vector<PixelRect>{};
  // The balls that stay as they were: mirrors of the change.
  std::vector<BoundCapsule> still;
  for (std::size_t i = 0; i < frame.parts.size(); ++i)
    if (frame.parts[i].mirrors && reference.parts[i].text == frame.parts[i].text)
      still.insert(still.end(), frame.parts[i].seen.begin(), frame.parts[i].seen.end());
  // The lamp shade's lacquer may show what changed and any ball (what the balls show of it included).
  std::vector<Hull> shade_shows = hulls;
  for (const BoundCapsule& c : still) shade_shows.push_back({c.a, c.b});
  // Each ball that stays as it was may show it in its clear coat, in a patch of its own.
  add_mirror_patches(still, frame.camera_pose.location, scene, hulls);

  const PixelProjection projection(frame.camera_pose, width, height);
  std::vector<PixelRect> rects;
  for (const Hull& hull : hulls) {
    rects.push_back(projection.bound(hull));
  }
  add_shade_mirror(frame.camera_pose.location, shade_shows, scene, projection, rects);
  rects = merge_regions(std::move(rects));
  long cost = 0;
  for (const PixelRect& r : rects) cost += r.area() + kRegionStartPixels;
  if (static_cast<double>(cost) >= kWholeShare * (static_cast<double>(width) * height + kRegionStartPixels))
    return std::nullopt;
  return rects;
}

}  // namespace bsim
