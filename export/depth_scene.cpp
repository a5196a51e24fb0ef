#include "depth_scene.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "number_format.h"
#include "pocket_fall.h"
#include "scene.h"
#include "table.h"
#include "text_words.h"

namespace bsim {

std::vector<DepthPlane> polygon_planes(const std::vector<Vec3>& corners) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : corners) centre += flat(c);
  centre /= static_cast<double>(corners.size());
  std::vector<DepthPlane> planes;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = flat(corners[i]), b = flat(corners[(i + 1) % corners.size()]);
    Vec3 n(b.y() - a.y(), a.x() - b.x(), 0);
    if (n.norm() < 1e-12) continue;
    n.normalize();
    if (n.dot(centre - a) > 0) n = -n;
    planes.push_back({n, n.dot(a)});
  }
  return planes;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- numbers of the POV-Ray models (export/pov/settings.inc, table.inc) the table description leaves out
constexpr double kApronDepth = 0.23;    ///< m, the rails' face below the bed (ApronDepth)
constexpr double kSlateDepth = 0.028;   ///< m, the slate (SlateDepth)
constexpr double kBevel = 0.016;        ///< m, the rails' outer bevel (Bevel)
constexpr double kCushionBack = 0.012;  ///< m the cushion reaches into the wood behind its top

/// A box.
DepthSolid box_solid(const Vec3& low, const Vec3& high) {
  DepthSolid s;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 n = Vec3::Zero();
    n[axis] = 1;
    s.planes.push_back({n, high[axis]});
    s.planes.push_back({-n, -low[axis]});
  }
  s.low = low;
  s.high = high;
  return s;
}

/// An upright prism over a convex polygon, from z0 to z1.
DepthSolid prism_solid(const std::vector<Vec3>& corners, double z0, double z1) {
  DepthSolid s;
  s.planes = polygon_planes(corners);
  s.planes.push_back({Vec3::UnitZ(), z1});
  s.planes.push_back({-Vec3::UnitZ(), -z0});
  s.low = Vec3(kInf, kInf, z0);
  s.high = Vec3(-kInf, -kInf, z1);
  for (const Vec3& c : corners) {
    s.low = s.low.cwiseMin(Vec3(c.x(), c.y(), z0));
    s.high = s.high.cwiseMax(Vec3(c.x(), c.y(), z1));
  }
  return s;
}

int add_disc(DepthScene& scene, const Vec3& centre, double radius) {
  DepthColumn c;
  c.cx = centre.x();
  c.cy = centre.y();
  c.radius = radius;
  scene.columns.push_back(c);
  return static_cast<int>(scene.columns.size()) - 1;
}

int add_polygon(DepthScene& scene, std::vector<Vec3> corners) {
  DepthColumn c;
  c.disc = false;
  c.corners = std::move(corners);
  scene.columns.push_back(c);
  return static_cast<int>(scene.columns.size()) - 1;
}

/// The columns of a pocket's opening through the wood grown by `grow` (table.inc's Throat): a jawed
/// pocket's throat, the polygon between its facings and its round back; a bare pocket's drop circle.
std::vector<int> throat_columns(DepthScene& scene, const PocketMouth& m, double grow) {
  if (!m.jawed()) return {add_disc(scene, m.centre, m.drop_radius + grow)};
  std::array<Vec3, 2> n, t;
  for (int k = 0; k < 2; ++k) {
    const Vec3 f = m.tangent[k] - m.nose[k];
    n[k] = m.nose[k] - m.inward[k] * grow - f * (grow / f.norm());
    t[k] = m.tangent[k] - m.inward[k] * grow;
  }
  return {add_disc(scene, m.throat_centre, m.throat_radius + grow), add_polygon(scene, {n[0], t[0], t[1], n[1]})};
}

/// The hole through the slate (table.inc's Hole): a cut pocket's drop circle, else its throat too.
std::vector<int> hole_columns(DepthScene& scene, const PocketMouth& m) {
  std::vector<int> columns = {add_disc(scene, m.centre, m.drop_radius)};
  if (!m.cut) {
    const std::vector<int> throat = throat_columns(scene, m, 0);
    columns.insert(columns.end(), throat.begin(), throat.end());
  }
  return columns;
}

/// How far a cushion reaches past its nose end (table.inc's CushionExt).
double cushion_extension(const CushionEnd& end) {
  const double w = kStandardTable.cushion.width;
  return end.pocket < 0 ? w : end.slant * (w + kCushionBack) + 0.005;
}

/// Cushion i: its nose profile swept along its nose line, from past one end to past the other, cut
/// along the facing of each jaw it ends in.
DepthSolid cushion_solid(const Scene& scene, const TableLayout& layout, int i) {
  const Rail& rail = scene.rails[static_cast<std::size_t>(i)];
  const Vec3 a = flat(rail.a), along = (flat(rail.b) - a).normalized();
  const Vec3 out(-along.y(), along.x(), 0);  // from the nose into the cushion
  const double length = (flat(rail.b) - a).norm(), h = rail.a.z(), top = layout.cushion_top;
  const double w = kStandardTable.cushion.width, back = w + kCushionBack;
  // The profile (m out from the nose, m up; table.inc's Cushion), from its foot round the nose to its
  // top and back down behind it: its convex hull, which leaves out the model's one hollow, at most
  // 1.5 mm deep, where the nose's top meets the slope up to the wood.
  const std::vector<Vec3> profile = {Vec3(kStandardTable.cushion.undercut, 0, 0),
                                     Vec3(0.0055, 0.52 * h, 0),
                                     Vec3(0.0012, 0.85 * h, 0),
                                     Vec3(0, h, 0),
                                     Vec3(0.0006, h + 0.0016, 0),
                                     Vec3(0.0035, h + 0.0034, 0),
                                     Vec3(w, top, 0),
                                     Vec3(back, top, 0),
                                     Vec3(back, 0, 0)};
  DepthSolid s;
  for (const DepthPlane& p : polygon_planes(profile)) {
    // (u, v) = (out . q - out . a, q.z): the profile's half-plane in the world.
    const double nu = p.normal.x(), nv = p.normal.y();
    s.planes.push_back({Vec3(nu * out.x(), nu * out.y(), nv), p.offset + nu * out.dot(a)});
  }
  const std::size_t k = static_cast<std::size_t>(i);
  const double ext_a = cushion_extension(layout.ends_a[k]), ext_b = cushion_extension(layout.ends_b[k]);
  s.planes.push_back({-along, ext_a - along.dot(a)});
  s.planes.push_back({along, length + ext_b + along.dot(a)});
  for (const PocketMouth& m : layout.pockets)
    for (int j = 0; j < 2; ++j)
      if (m.jawed() && m.rail[j] == i)
        s.planes.push_back({Vec3(m.inward[j].x(), m.inward[j].y(), 0), flat(m.inward[j]).dot(flat(m.nose[j]))});
  s.low = Vec3(kInf, kInf, 0);
  s.high = Vec3(-kInf, -kInf, top);
  for (double along_at : {-ext_a, length + ext_b})
    for (double u : {0.0, back}) {
      const Vec3 q = a + along_at * along + u * out;
      s.low = s.low.cwiseMin(Vec3(q.x(), q.y(), 0));
      s.high = s.high.cwiseMax(Vec3(q.x(), q.y(), top));
    }
  return s;
}

/// The wooden rails: four mitred pieces from the wood's inner edge to the table's outer edge, the
/// outer top edge bevelled at 45 degrees, less the pockets' throats and the liners in them.
void add_rails(DepthScene& scene, const TableLayout& layout, const std::vector<int>& throats) {
  const TableRect in = layout.wood_inner, out = layout.wood_outer;
  struct Piece {
    std::vector<Vec3> corners;
    Vec3 outward;
  };
  const std::array<Piece, 4> pieces = {{
      {{Vec3(in.x0, in.y1, 0), Vec3(in.x1, in.y1, 0), Vec3(out.x1, out.y1, 0), Vec3(out.x0, out.y1, 0)}, Vec3(0, 1, 0)},
      {{Vec3(in.x1, in.y0, 0), Vec3(in.x0, in.y0, 0), Vec3(out.x0, out.y0, 0), Vec3(out.x1, out.y0, 0)},
       Vec3(0, -1, 0)},
      {{Vec3(in.x1, in.y1, 0), Vec3(in.x1, in.y0, 0), Vec3(out.x1, out.y0, 0), Vec3(out.x1, out.y1, 0)}, Vec3(1, 0, 0)},
      {{Vec3(in.x0, in.y0, 0), Vec3(in.x0, in.y1, 0), Vec3(out.x0, out.y1, 0), Vec3(out.x0, out.y0, 0)},
       Vec3(-1, 0, 0)},
  }};
  for (const Piece& piece : pieces) {
    DepthSolid s = prism_solid(piece.corners, -kApronDepth, layout.rail_top);
    // The bevel: a plane through the outer top edge pulled in by kBevel, leaning out at 45 degrees.
    const Vec3 n(piece.outward.x(), piece.outward.y(), 1);
    const Vec3 q = piece.corners[2] - kBevel * piece.outward + Vec3(0, 0, layout.rail_top);
    s.planes.push_back({n, n.dot(q)});
    s.holes = throats;
    scene.solids.push_back(std::move(s));
  }
}

/// The slate bed and each cut pocket's shelf, less the holes; under each hole its cup.
void add_bed(DepthScene& scene, const TableLayout& layout) {
  DepthSolid bed = box_solid(Vec3(layout.wood_inner.x0, layout.wood_inner.y0, -kSlateDepth),
                             Vec3(layout.wood_inner.x1, layout.wood_inner.y1, 0));
  const double cup_floor = -kPocketDepth - 0.0005;  // table.inc's CupFloorZ
  for (const PocketMouth& m : layout.pockets) {
    const std::vector<int> hole = hole_columns(scene, m);
    bed.holes.insert(bed.holes.end(), hole.begin(), hole.end());
    if (m.cut) {
      DepthSolid shelf = prism_solid({m.nose[0], m.tangent[0], m.tangent[1], m.nose[1]}, -kSlateDepth, 0);
      shelf.holes = hole;
      scene.solids.push_back(std::move(shelf));
    }
    scene.cups.push_back({m.centre.x(), m.centre.y(), m.drop_radius, cup_floor, 0});
  }
  scene.solids.push_back(std::move(bed));
}

/// The body under the rails, the four legs and the lamp's shade, as boxes.
void add_boxes(DepthScene& scene, const TableLayout& layout) {
  const TableRect out = layout.wood_outer;
  scene.solids.push_back(box_solid(Vec3(out.x0 + 0.06, out.y0 + 0.06, -kApronDepth - 0.12),
                                   Vec3(out.x1 - 0.06, out.y1 - 0.06, -kApronDepth)));
  for (int i = 0; i < 4; ++i) {
    const double x = i < 2 ? out.x0 + 0.22 : out.x1 - 0.22, y = i % 2 == 0 ? out.y0 + 0.22 : out.y1 - 0.22;
    scene.solids.push_back(box_solid(Vec3(x - 0.09, y - 0.09, layout.floor), Vec3(x + 0.09, y + 0.09, -kApronDepth)));
  }
  scene.solids.push_back(box_solid(Vec3(layout.lamp.x0, layout.lamp.y0, layout.lamp_bottom),
                                   Vec3(layout.lamp.x1, layout.lamp.y1, layout.lamp_top)));
}

}  // namespace

DepthScene depth_scene(const Scene& scene) {
  DepthScene d;
  d.ball_radius = scene.physics.ball_radius;
  const TableLayout layout = table_layout(scene);
  add_bed(d, layout);
  for (int i = 0; i < static_cast<int>(scene.rails.size()); ++i) d.solids.push_back(cushion_solid(scene, layout, i));
  std::vector<int> throats;
  for (const PocketMouth& m : layout.pockets) {
    const std::vector<int> t = throat_columns(d, m, kStandardTable.jaws.liner);
    throats.insert(throats.end(), t.begin(), t.end());
  }
  add_rails(d, layout, throats);
  add_boxes(d, layout);
  const TableRect out = layout.wood_outer;
  d.room_low = Vec3(out.x0 - kRoom.margin, out.y0 - kRoom.margin, layout.floor);
  d.room_high = Vec3(out.x1 + kRoom.margin, out.y1 + kRoom.margin, kRoom.ceiling);
  return d;
}

// ---- the text form: one line a column, solid and cup, words then numbers separated by spaces

namespace {

void put(std::string& out, double value) {
  out += ' ';
  append_number(out, value);
}
void put(std::string& out, const Vec3& v) {
  for (int i = 0; i < 3; ++i) put(out, v[i]);
}

bool take_count(std::istringstream& in, std::size_t& n, std::size_t most) {
  double value = 0;
  if (!take(in, value) || value < 0 || value > static_cast<double>(most) || value != std::floor(value)) return false;
  n = static_cast<std::size_t>(value);
  return true;
}

bool parse_column(std::istringstream& in, DepthColumn& c) {
  std::string kind;
  in >> kind;
  if (kind == "disc") return take(in, c.cx) && take(in, c.cy) && take(in, c.radius) && c.radius >= 0;
  std::size_t n = 0;
  if (kind != "polygon" || !take_count(in, n, 64) || n < 3) return false;
  c.disc = false;
  c.corners.resize(n);
  for (Vec3& p : c.corners)
    if (!take(in, p.x()) || !take(in, p.y())) return false;
  return true;
}

bool parse_solid(std::istringstream& in, std::size_t columns, DepthSolid& s) {
  std::size_t n = 0;
  if (!take(in, s.low) || !take(in, s.high) || !word_is(in, "planes") || !take_count(in, n, 64)) return false;
  s.planes.resize(n);
  for (DepthPlane& p : s.planes)
    if (!take(in, p.normal) || !take(in, p.offset)) return false;
  if (!word_is(in, "holes") || !take_count(in, n, 1024)) return false;
  s.holes.resize(n);
  for (int& h : s.holes) {
    std::size_t index = 0;
    if (!take_count(in, index, columns == 0 ? 0 : columns - 1)) return false;
    h = static_cast<int>(index);
  }
  return true;
}

}  // namespace

std::string depth_scene_text(const DepthScene& scene) {
  std::string out = "ball";
  put(out, scene.ball_radius);
  out += "\nroom";
  put(out, scene.room_low);
  put(out, scene.room_high);
  for (const DepthColumn& c : scene.columns) {
    out += c.disc ? "\ncolumn disc" : "\ncolumn polygon";
    if (c.disc) {
      put(out, c.cx);
      put(out, c.cy);
      put(out, c.radius);
      continue;
    }
    put(out, static_cast<double>(c.corners.size()));
    for (const Vec3& p : c.corners) {
      put(out, p.x());
      put(out, p.y());
    }
  }
  for (const DepthSolid& s : scene.solids) {
    out += "\nsolid";
    put(out, s.low);
    put(out, s.high);
    out += " planes";
    put(out, static_cast<double>(s.planes.size()));
    for (const DepthPlane& p : s.planes) {
      put(out, p.normal);
      put(out, p.offset);
    }
    out += " holes";
    put(out, static_cast<double>(s.holes.size()));
    for (int h : s.holes) put(out, h);
  }
  for (const DepthCup& c : scene.cups) {
    out += "\ncup";
    for (double v : {c.cx, c.cy, c.radius, c.z0, c.z1}) put(out, v);
  }
  return out;
}

bool parse_depth_scene(const std::string& text, DepthScene& scene, std::string& error) {
  scene = {};
  std::istringstream lines(text);
  int number = 0;
  bool ball = false, room = false;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    std::istringstream in(line);
    std::string word;
    if (!(in >> word)) continue;
    bool ok = false;
    if (word == "ball") {
      ok = ball = take(in, scene.ball_radius) && scene.ball_radius > 0;
    } else if (word == "room") {
      ok = room = take(in, scene.room_low) && take(in, scene.room_high);
    } else if (word == "column") {
      ok = parse_column(in, scene.columns.emplace_back());
    } else if (word == "solid") {
      ok = parse_solid(in, scene.columns.size(), scene.solids.emplace_back());
    } else if (word == "cup") {
      DepthCup& c = scene.cups.emplace_back();
      ok = take(in, c.cx) && take(in, c.cy) && take(in, c.radius) && take(in, c.z0) && take(in, c.z1);
    }
    std::string rest;
    if (!ok || in >> rest) {
      error = "line " + std::to_string(number) + " is not part of a scene: " + line.substr(0, 40);
      return false;
    }
  }
  if (!ball || !room) {
    error = std::string("the scene has no ") + (ball ? "room" : "ball") + " line";
    return false;
  }
  return true;
}

}  // namespace bsim
