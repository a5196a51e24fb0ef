// One table for every reader: the physics' standard table, the cue stick's clearance, the GL
// preview's meshes and the POV-Ray include all take the cushion, the wood and the sights from
// kStandardTable and table_layout().
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cue_geometry.h"
#include "pocket_fall.h"
#include "pov_format.h"
#include "pov_table.h"
#include "scene.h"
#include "shots.h"
#include "table.h"
#include "table_model.h"

using namespace bsim;

namespace {

Scene standard_scene() {
  Scene scene;
  scene.rails = standard_rails();
  scene.pockets = standard_pockets();
  return scene;
}

std::string include_text(const Scene& scene) {
  std::ostringstream out;
  write_pov_include(scene, Quality::draft, out);
  return out.str();
}

/// The value of `#declare NAME = VALUE;` in a POV-Ray include, or "" when it is not there.
std::string declared(const std::string& text, const std::string& name) {
  const std::string key = "#declare " + name + " = ";
  const auto at = text.find(key);
  if (at == std::string::npos) return "";
  const auto begin = at + key.size();
  return text.substr(begin, text.find(';', begin) - begin);
}

struct Extent {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9, z1 = -1e9;
};

Extent extent(const MeshData& mesh) {
  Extent e;
  for (const Vertex& v : mesh.vertices) {
    e.x0 = std::min<double>(e.x0, v.position[0]);
    e.y0 = std::min<double>(e.y0, v.position[1]);
    e.x1 = std::max<double>(e.x1, v.position[0]);
    e.y1 = std::max<double>(e.y1, v.position[1]);
    e.z1 = std::max<double>(e.z1, v.position[2]);
  }
  return e;
}

constexpr double kFloat = 1e-6;  // m, the meshes hold floats

double degrees(double radians) { return radians * 180 / 3.14159265358979323846; }

/// The direction along pocket jaw i's cushion, away from the pocket.
Vec3 along_cushion(const Scene& scene, const PocketMouth& m, int i) {
  const Rail& r = scene.rails[static_cast<std::size_t>(m.rail[i])];
  Vec3 d = m.at_b[i] ? Vec3(r.a - r.b) : Vec3(r.b - r.a);
  d.z() = 0;
  return d.normalized();
}

/// m between a pocket's facings `behind` m behind its mouth, along its axis.
double width_behind(const PocketMouth& m, double behind) {
  if (!m.jawed()) return 2 * m.drop_radius;
  const Vec3 middle = (m.nose[0] + m.nose[1]) / 2;
  double width = 0;
  for (int i = 0; i < 2; ++i) {
    // The facing's point `behind` along the axis, measured from the mouth's line.
    const double run = (behind - (m.nose[i] - middle).dot(m.axis)) / m.facing[i].dot(m.axis);
    const Vec3 p = m.nose[i] + run * m.facing[i];
    width += std::abs((p - middle).dot(Vec3(-m.axis.y(), m.axis.x(), 0)));
  }
  return width;
}

/// Whether p (z ignored) lies in a pocket's throat or drop circle: what the bed and the cup leave open.
bool in_hole(const PocketMouth& m, const Vec3& p) {
  return (Vec3(p.x(), p.y(), 0) - m.centre).norm() <= m.drop_radius || m.in_throat(p);
}

/// The items of `#declare NAME = array[N] { ... }` in a POV-Ray include, each as written (a number,
/// or a vector `<u, v>`).
std::vector<std::string> array_items(const std::string& text, const std::string& name) {
  std::string body = declared(text, name);
  std::vector<std::string> items;
  const auto open = body.find('{'), close = body.find('}');
  if (open == std::string::npos || close == std::string::npos) return items;
  body = body.substr(open + 1, close - open - 1);
  for (std::size_t at = 0; at < body.size();) {
    while (at < body.size() && (body[at] == ' ' || body[at] == ',')) ++at;
    if (at >= body.size()) break;
    const std::size_t end = body[at] == '<' ? body.find('>', at) + 1 : body.find(',', at);
    std::string item = body.substr(at, end == std::string::npos ? std::string::npos : end - at);
    while (!item.empty() && item.back() == ' ') item.pop_back();
    items.push_back(item);
    at = end == std::string::npos ? body.size() : end;
  }
  return items;
}

/// A point written as `<u, v>` in the include.
Vec3 point_of(const std::string& item) {
  double u = 0, v = 0;
  REQUIRE(std::sscanf(item.c_str(), "<%lf, %lf>", &u, &v) == 2);
  return Vec3(u, v, 0);
}

/// m from plan point p to the segment a-b.
double to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double t = std::clamp((flat(p) - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (flat(p) - (a + t * (b - a))).norm();
}

/// One cut pocket as the POV-Ray include draws it, read back from its arrays.
struct DrawnPocket {
  Vec3 hole{0, 0, 0};
  double hole_radius = 0, round_radius = 0;
  Vec3 round_centre[2], face_start[2], tangent[2];

  /// m from plan point p to the drawn jaw i: its rounding's arc or its facing, from the rounding to the hole.
  double to_jaw(const Vec3& p, int i) const {
    return std::min(std::abs((flat(p) - round_centre[i]).norm() - round_radius),
                    to_segment(p, face_start[i], tangent[i]));
  }
};

std::vector<DrawnPocket> drawn_pockets(const std::string& text) {
  const auto c = array_items(text, "PocketC"), r = array_items(text, "PocketR"), rr = array_items(text, "JawRoundR");
  for (const char* name :
       {"PocketR", "JawRoundR", "JawRoundC0", "JawRoundC1", "JawFaceStart0", "JawFaceStart1", "ThroatT0", "ThroatT1"}) {
    CAPTURE(name);
    REQUIRE(array_items(text, name).size() == c.size());
  }
  std::vector<DrawnPocket> pockets(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    DrawnPocket& p = pockets[k];
    p.hole = point_of(c[k]);
    p.hole_radius = std::stod(r[k]);
    p.round_radius = std::stod(rr[k]);
    for (int i = 0; i < 2; ++i) {
      const std::string n = std::to_string(i);
      p.round_centre[i] = point_of(array_items(text, "JawRoundC" + n)[k]);
      p.face_start[i] = point_of(array_items(text, "JawFaceStart" + n)[k]);
      p.tangent[i] = point_of(array_items(text, "ThroatT" + n)[k]);
    }
  }
  return pockets;
}

}  // namespace

TEST_SUITE("table model") {
  TEST_CASE("the physics' standard table is the description's") {
    const TableSpec& t = kStandardTable;
    const auto rails = standard_rails();
    const auto pockets = standard_pockets();
    REQUIRE(rails.size() == 6);
    REQUIRE(pockets.size() == 6);
    for (const Rail& r : rails) {
      CHECK(r.a.z() == t.nose_height);
      CHECK(r.b.z() == t.nose_height);
    }
    CHECK(rails[2].a.x() == t.half_length);
    CHECK(rails[0].a.y() == t.half_width);
    // The rails end at the jaw points: the WPA mouths between them, 4.5 to 4.625 in at a corner, 5 to
    // 5.125 in at a side.
    const PhysicsParams params;
    CHECK(rails[0].a.x() == doctest::Approx(-t.half_length + params.corner_mouth / std::sqrt(2.0)));
    CHECK((rails[0].a - rails[5].b).norm() == doctest::Approx(params.corner_mouth));
    CHECK((rails[1].a - rails[0].b).norm() == doctest::Approx(params.side_mouth));
    CHECK(params.corner_mouth >= 4.5 * 0.0254);
    CHECK(params.corner_mouth <= 4.625 * 0.0254);
    CHECK(params.side_mouth >= 5 * 0.0254);
    CHECK(params.side_mouth <= 5.125 * 0.0254);
    CHECK(pockets[0].radius == t.jaws.corner_hole);
    CHECK(pockets[1].radius == t.jaws.side_hole);
    CHECK(kStandardNoseHeight == t.nose_height);
  }

  TEST_CASE("real 9-foot numbers: a 5 cm cushion, a rail within the WPA's 4 to 7 1/2 in, 18 sights") {
    const TableSpec& t = kStandardTable;
    CHECK(t.cushion.width == doctest::Approx(0.05));
    CHECK(t.rail_reach() >= 0.1016);
    CHECK(t.rail_reach() <= 0.1905);
    CHECK(t.rail.top_rise > t.cushion.top_rise);  // the wood stands a little proud of the cushion
    CHECK(table_layout(standard_scene()).sights.size() == 18);
  }

  TEST_CASE(
      "the layout grows the noses by the cushion, then the wood; a scene without cushions gets the standard bed") {
    const TableLayout layout = table_layout(standard_scene());
    const TableSpec& t = kStandardTable;
    CHECK(layout.noses.x1 == t.half_length);
    CHECK(layout.noses.y0 == -t.half_width);
    CHECK(layout.wood_inner.x1 == doctest::Approx(t.half_length + t.cushion.width));
    CHECK(layout.wood_outer.y1 == doctest::Approx(t.half_width + t.rail_reach()));
    CHECK(layout.rail_top == doctest::Approx(t.nose_height + t.rail.top_rise));
    CHECK(layout.cushion_top == doctest::Approx(t.nose_height + t.cushion.top_rise));
    for (const SightPlace& s : layout.sights) {
      const double from_nose =
          s.along_x ? std::abs(s.centre.y()) - t.half_width : std::abs(s.centre.x()) - t.half_length;
      CHECK(from_nose == doctest::Approx(t.sights.from_nose));
      CHECK(s.centre.z() == layout.rail_top);
    }

    Scene bare;
    bare.pockets = standard_pockets();
    const TableLayout standard = table_layout(bare);
    CHECK(standard.noses.x0 == -t.half_length);
    CHECK(standard.noses.y1 == t.half_width);
    CHECK(standard.nose_height == t.nose_height);

    Scene high = standard_scene();
    for (Rail& r : high.rails) r.a.z() = r.b.z() = 0.05;
    CHECK(table_layout(high).rail_top == doctest::Approx(0.05 + t.rail.top_rise));
  }

  TEST_CASE("the preview's cushion and wood come from the model") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const TableModel model = build_table_model(scene);
    const Extent cloth = extent(model.cloth);
    CHECK(cloth.x1 == doctest::Approx(layout.noses.x1 + kStandardTable.cushion.width).epsilon(kFloat));
    CHECK(cloth.y0 == doctest::Approx(layout.noses.y0 - kStandardTable.cushion.width).epsilon(kFloat));
    const Extent tops = extent(model.tops);
    CHECK(tops.x1 == doctest::Approx(layout.noses.x1 + kStandardTable.rail_reach()).epsilon(kFloat));
    CHECK(tops.y1 == doctest::Approx(layout.noses.y1 + kStandardTable.rail_reach()).epsilon(kFloat));
    CHECK(model.top_height == layout.rail_top);
  }

  TEST_CASE("the POV-Ray include declares the same model, not numbers of its own") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const std::string text = include_text(scene);
    CHECK(declared(text, "CushionW") == pov_number(kStandardTable.cushion.width));
    CHECK(declared(text, "CushionUndercut") == pov_number(kStandardTable.cushion.undercut));
    CHECK(declared(text, "CushionTopZ") == pov_number(layout.cushion_top));
    CHECK(declared(text, "RailW") == pov_number(kStandardTable.rail.width));
    CHECK(declared(text, "RailTopZ") == pov_number(layout.rail_top));
    CHECK(declared(text, "FloorZ") == pov_number(-kStandardTable.bed_height));
    CHECK(declared(text, "SightLength") == pov_number(kStandardTable.sights.length));
    CHECK(declared(text, "SightWidth") == pov_number(kStandardTable.sights.width));
    CHECK(declared(text, "SightCount") == std::to_string(layout.sights.size()));
    const SightPlace& first = layout.sights.front();
    CHECK(declared(text, "SightC").find("{ " + pov_vector2(first.centre.x(), first.centre.y()) + ",") !=
          std::string::npos);
    // Each number is declared once, from the model: the fixed models hold none of their own.
    for (const char* name : {"CushionW", "RailW", "RailTopZ", "FloorZ"})
      CHECK(std::string(pov_models_text()).find(std::string("#declare ") + name) == std::string::npos);
  }

  TEST_CASE("the preview and POV-Ray agree on a table of the scene's own") {
    Scene scene;
    for (const auto& [a, b] : {std::pair{Vec3(-1.5, 0.8, 0.04), Vec3(1.5, 0.8, 0.04)},
                               std::pair{Vec3(1.5, 0.8, 0.04), Vec3(1.5, -0.8, 0.04)},
                               std::pair{Vec3(1.5, -0.8, 0.04), Vec3(-1.5, -0.8, 0.04)},
                               std::pair{Vec3(-1.5, -0.8, 0.04), Vec3(-1.5, 0.8, 0.04)}})
      scene.rails.push_back(Rail{a, b, {}});
    const TableModel model = build_table_model(scene);
    const std::string text = include_text(scene);
    CHECK(declared(text, "RailTopZ") == pov_number(model.top_height));
    const Extent cloth = extent(model.cloth);
    CHECK(declared(text, "CushionW") == pov_number(std::round((cloth.x1 - 1.5) * 1e6) / 1e6));
    const Extent tops = extent(model.tops);
    CHECK(pov_number(std::round((tops.x1 - cloth.x1) * 1e6) / 1e6) == declared(text, "RailW"));
  }

  TEST_CASE("the cue stick clears the model's cushion and wood, and nothing beyond them") {
    const Scene scene = standard_scene();
    const TableSpec& t = kStandardTable;
    // A level stick along the top long cushions (over both, across the side pocket), its lowest point
    // (the butt) 2 mm above the wood's top.
    const double z = t.nose_height + t.rail.top_rise + kCueButtRadius + 0.002;
    const auto stick_at = [&](double from_nose) {
      CuePose pose;
      pose.tip = Vec3(-0.7, t.half_width + from_nose, z);
      pose.axis = Vec3(1, 0, 0);
      pose.visible = true;
      return pose;
    };
    // Over the wood's outer edge: the block the model draws is the one the stick must clear.
    CHECK(stick_clearance(stick_at(t.rail_reach() - 0.005), scene, {}, 0.028575) == doctest::Approx(0.002));
    // Beyond the table's outer edge by more than the stick is thick only the bed's plane is left to clear.
    CHECK(stick_clearance(stick_at(t.rail_reach() + kCueButtRadius + 0.001), scene, {}, 0.028575) ==
          doctest::Approx(z - kCueButtRadius));
    // Beside the edge by less, the stick's round overhangs the wood: what lies over it clears it by
    // less than the stick's lowest line clears the bed, but more than that line would clear the wood.
    const double overhang = stick_clearance(stick_at(t.rail_reach() + 0.005), scene, {}, 0.028575);
    CHECK(overhang > 0.002);
    CHECK(overhang < z - kCueButtRadius);
  }

  TEST_CASE("pockets: corner and side jaws from the nose lines, cut along facings at the WPA's 142 and 104 degrees") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    REQUIRE(layout.pockets.size() == 6);
    const PocketKind kinds[] = {PocketKind::corner, PocketKind::side, PocketKind::corner,
                                PocketKind::corner, PocketKind::side, PocketKind::corner};
    for (std::size_t k = 0; k < 6; ++k) {
      const PocketMouth& m = layout.pockets[k];
      CAPTURE(k);
      REQUIRE(m.kind == kinds[k]);
      const double want = m.kind == PocketKind::corner ? 142.0 : 104.0;
      CHECK(m.facing_deg == want);
      for (int i = 0; i < 2; ++i) {
        const Rail& r = scene.rails[static_cast<std::size_t>(m.rail[i])];
        // The facing starts at the nose end, the end of the scene's rail segment at the pocket...
        const Vec3 end = m.at_b[i] ? r.b : r.a;
        CHECK((m.nose[i] - Vec3(end.x(), end.y(), 0)).norm() < 1e-12);
        // ...and turns from the nose by the WPA angle, into the cushion (away from the bed).
        CHECK(degrees(std::acos(along_cushion(scene, m, i).dot(m.facing[i]))) == doctest::Approx(want));
        CHECK(m.facing[i].dot(m.axis) > 0);
        CHECK(m.facing[i].dot(m.inward[i]) == doctest::Approx(0).epsilon(1e-12));
        // The cushion end's slant is the facing's: it runs on past the nose end by cot(180 - angle).
        const CushionEnd& cut = (m.at_b[i] ? layout.ends_b : layout.ends_a)[static_cast<std::size_t>(m.rail[i])];
        CHECK(cut.pocket == static_cast<int>(k));
        CHECK(degrees(std::atan(1 / cut.slant)) == doctest::Approx(180 - want));
      }
      // The throat closes in behind the mouth, and is still wider than a ball where it meets the wood.
      CHECK(width_behind(m, 0) == doctest::Approx(m.mouth()));
      CHECK(width_behind(m, 0.03) < m.mouth());
      CHECK(width_behind(m, 0.05) > 2 * 0.028575 + 0.02);
    }
    // WPA mouths: corner 4.5 to 4.625 in, side 5 to 5.125 in (the drop circles put the noses there).
    CHECK(layout.pockets[0].mouth() == doctest::Approx(0.1143).epsilon(0.02));
    CHECK(layout.pockets[1].mouth() == doctest::Approx(0.1270).epsilon(0.03));
  }

  TEST_CASE("pockets: the drop circle stays open, the cup holds every resting ball, the throat reaches the wood") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const double R = 0.028575;
    for (const PocketMouth& m : layout.pockets) {
      CAPTURE(m.centre.x());
      CAPTURE(m.centre.y());
      for (int k = 0; k < 64; ++k) {
        const double a = 2 * 3.14159265358979323846 * k / 64;
        const Vec3 dir(std::cos(a), std::sin(a), 0);
        // Every point of the drop circle is open (the bed's hole is the circle and the throat).
        CHECK(in_hole(m, m.centre + dir * (m.drop_radius - 1e-9)));
        // A ball resting anywhere the fall leaves it (its centre inside the physics' wall, R in from
        // the circle) lies wholly in the cup.
        for (int j = 0; j < 16; ++j) {
          const double b = 2 * 3.14159265358979323846 * j / 16;
          CHECK(in_hole(m, m.centre + dir * (m.drop_radius - R) + Vec3(std::cos(b), std::sin(b), 0) * (R - 1e-9)));
        }
      }
      // The throat's round back lies behind the wood's inner edge: the opening goes through the rail.
      const Vec3 back = m.throat_centre + m.axis * m.throat_radius;
      CHECK(!(back.x() > layout.wood_inner.x0 && back.x() < layout.wood_inner.x1 && back.y() > layout.wood_inner.y0 &&
              back.y() < layout.wood_inner.y1));
      // Between the facings it is open, outside them (in the cushion) not.
      const Vec3 middle = (m.nose[0] + m.nose[1]) / 2;
      CHECK(m.in_throat(middle + m.axis * 0.02));
      for (int i = 0; i < 2; ++i) CHECK(!m.in_throat(m.nose[i] + m.facing[i] * 0.02 - m.inward[i] * 0.005));
    }
    // A pocket no cushion end meets opens on its drop circle alone.
    Scene box;
    box.rails = {Rail{Vec3(-1, 0.5, 0.04), Vec3(1, 0.5, 0.04), {}}};
    box.pockets = {Pocket{Vec3(0.2, -0.3, 0), 0.07, {}}};
    const TableLayout bare = table_layout(box);
    REQUIRE(bare.pockets.size() == 1);
    CHECK(bare.pockets[0].kind == PocketKind::bare);
    CHECK(bare.pockets[0].in_throat(Vec3(0.2 + 0.069, -0.3, 0)));
    CHECK(!bare.pockets[0].in_throat(Vec3(0.2 + 0.071, -0.3, 0)));
    CHECK(bare.ends_a[0].pocket == -1);
    CHECK(bare.ends_b[0].pocket == -1);
  }

  TEST_CASE("pockets: the preview and POV-Ray draw the same jaws and throats") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const std::string text = include_text(scene);
    const PocketMouth& corner = layout.pockets[0];
    CHECK(declared(text, "JawNose0").find("{ " + pov_vector2(corner.nose[0].x(), corner.nose[0].y()) + ",") !=
          std::string::npos);
    CHECK(declared(text, "ThroatR").find("{ " + pov_number(corner.throat_radius) + ",") != std::string::npos);
    CHECK(declared(text, "PocketLinerT") == pov_number(kStandardTable.jaws.liner));
    // The preview cuts the wood's top by the same throat, grown by the liner: its mask reaches the
    // throat's round back.
    const TableModel model = build_table_model(scene);
    const Extent holes = extent(model.top_holes);
    const double back_x =
        corner.throat_centre.x() - (corner.throat_radius + kStandardTable.jaws.liner) * std::sqrt(0.5);
    CHECK(holes.x0 < back_x + 1e-3);
    CHECK(holes.x0 > corner.throat_centre.x() - corner.throat_radius - kStandardTable.jaws.liner - 1e-3);
    // The preview's cushion ends where the physics' jaw is: from the rounding's start on the nose,
    // through its end on the facing, along the facing to the hole's edge.
    const TableModel drawn = build_table_model(scene);
    for (const PocketMouth& m : layout.pockets)
      for (int i = 0; i < 2; ++i)
        for (const Vec3& p : {m.nose_end[i], m.face_start[i], m.tangent[i]}) {
          CAPTURE(p.x());
          CAPTURE(p.y());
          CHECK(std::any_of(drawn.body.vertices.begin(), drawn.body.vertices.end(), [&](const Vertex& v) {
            return std::hypot(v.position[0] - p.x(), v.position[1] - p.y()) < 1e-5;
          }));
        }
  }
  TEST_CASE("pockets: the include declares each cut pocket as the physics builds it, to the micrometre") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const std::string text = include_text(scene);
    const auto v2 = [](const Vec3& p) { return pov_vector2(p.x(), p.y()); };
    for (std::size_t k = 0; k < scene.pockets.size(); ++k) {
      CAPTURE(k);
      // The physics' own jaws, hole and shelf (what simulate.cpp's jaws are built from).
      const PocketMouth m = pocket_mouth(scene.pockets[k], scene.rails);
      REQUIRE(m.cut);
      CHECK(array_items(text, "PocketCut")[k] == "1");
      CHECK(array_items(text, "PocketC")[k] == v2(m.centre));
      CHECK(array_items(text, "PocketR")[k] == pov_number(m.drop_radius));
      CHECK(array_items(text, "PocketAxis")[k] == v2(m.axis));
      CHECK(array_items(text, "JawRoundR")[k] == pov_number(m.round_radius));
      for (int i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i);
        CHECK(array_items(text, "JawNose" + n)[k] == v2(m.nose[i]));
        CHECK(array_items(text, "JawIn" + n)[k] == v2(m.inward[i]));
        CHECK(array_items(text, "JawRoundC" + n)[k] == v2(m.round_centre[i]));
        CHECK(array_items(text, "JawNoseEnd" + n)[k] == v2(m.nose_end[i]));
        CHECK(array_items(text, "JawFaceStart" + n)[k] == v2(m.face_start[i]));
        CHECK(array_items(text, "ThroatT" + n)[k] == v2(m.tangent[i]));
      }
      // The layout every front end draws from is that same mouth.
      CHECK((layout.pockets[k].centre - m.centre).norm() == 0);
      CHECK((layout.pockets[k].tangent[1] - m.tangent[1]).norm() == 0);
    }
    // A scene's own pockets are not cut: drawn as before, the physics' drop circle alone.
    Scene own = standard_scene();
    own.pockets = bare_standard_pockets();
    CHECK(array_items(include_text(own), "PocketCut") == std::vector<std::string>(6, "0"));
  }

  TEST_CASE("pockets: balls bounce off the drawn jaws and drop through the drawn hole") {
    const std::vector<DrawnPocket> drawn = drawn_pockets(include_text(standard_scene()));
    REQUIRE(drawn.size() == 6);
    const double R = 0.028575, rise = kStandardTable.nose_height - R, reach = std::sqrt(R * R - rise * rise);
    int jaw_contacts = 0, drops = 0;
    // Lone balls rolled at the top-right corner and the top side pocket across the mouth, straight in
    // and at an angle, from the middle of each jaw to the other.
    struct Aim {
      Vec3 from, to;
    };
    std::vector<Aim> aims;
    for (int k = -12; k <= 12; ++k) {
      aims.push_back({Vec3(0.85, 0.2 + 0.01 * k, 0), Vec3(1.2288 + 0.004 * k, 0.5938 - 0.004 * k, 0)});
      aims.push_back({Vec3(-0.35 + 0.02 * k, 0.1, 0), Vec3(0.006 * k, 0.62, 0)});
    }
    for (const Aim& aim : aims) {
      const Vec3 v = (aim.to - aim.from).normalized() * 1.2;
      char text[160];
      std::snprintf(text, sizeof text, "cue 0 %.6f\nball 0 %.6f %.6f 0.028575  %.6f %.6f 0  1 0 0 0\n",
                    std::atan2(v.y(), v.x()) * 180 / 3.14159265358979323846, aim.from.x(), aim.from.y(), v.x(), v.y());
      const auto shot = test::load_scene(text, "aim");
      CAPTURE(text);
      for (const Event& e : shot->timeline.events()) {
        if (e.type != EventType::ball_jaw) continue;
        ++jaw_contacts;
        const DrawnPocket& p = drawn[static_cast<std::size_t>(e.pocket)];
        // The contact is on a drawn jaw, at the nose's height, the ball's centre as far from it as from
        // any cushion's nose (its radius, seen from above at the height the nose stands above the centre).
        CHECK(std::min(p.to_jaw(e.where, 0), p.to_jaw(e.where, 1)) < 3e-6);
        CHECK(e.where.z() == doctest::Approx(kStandardTable.nose_height));
        CHECK((flat(e.before.front().position) - flat(e.where)).norm() == doctest::Approx(reach).epsilon(1e-6));
      }
      for (const PocketDrop& d : shot->timeline.pocket_drops()) {
        ++drops;
        // The ball drops as its centre crosses the edge of the drawn hole.
        const DrawnPocket& p = drawn[static_cast<std::size_t>(d.pocket)];
        const Vec3 centre = shot->timeline.state(d.ball, d.time).position;
        CHECK((flat(centre) - p.hole).norm() == doctest::Approx(p.hole_radius).epsilon(3e-6 / p.hole_radius));
      }
    }
    CHECK(jaw_contacts >= 10);
    CHECK(drops >= 10);
  }

  TEST_CASE("pockets: the preview draws each cut pocket where the physics has it") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const TableModel model = build_table_model(scene);
    const double lip = kStandardTable.jaws.lip_round;
    for (const PocketMouth& m : layout.pockets) {
      CAPTURE(m.centre.x());
      CAPTURE(m.centre.y());
      // The bed is cut at the physics' hole (grown by the slate's rounded lip), not across the shelf.
      int hole_points = 0;
      for (const Vertex& v : model.bed_holes.vertices) {
        const double d = std::hypot(v.position[0] - m.centre.x(), v.position[1] - m.centre.y());
        if (d > 0.3) continue;
        ++hole_points;
        CHECK(d == doctest::Approx(m.drop_radius + lip).epsilon(1e-5));
      }
      CHECK(hole_points >= 48);
      // The wood's top is cut by that opening and its liner alone: every point of the mask lies in it.
      const MeshData& mask = model.top_holes;
      for (std::size_t t = 0; t + 2 < mask.indices.size(); t += 3) {
        Vec3 corner[3];
        for (int c = 0; c < 3; ++c) {
          const Vertex& v = mask.vertices[mask.indices[t + static_cast<std::size_t>(c)]];
          corner[c] = Vec3(v.position[0], v.position[1], 0);
        }
        if ((corner[0] - m.centre).norm() > 0.3) continue;
        for (double u : {0.05, 0.33, 0.6})
          for (double w : {0.05, 0.33, 0.6})
            if (u + w < 1)
              CHECK(m.in_throat(corner[0] + u * (corner[1] - corner[0]) + w * (corner[2] - corner[0]),
                                kStandardTable.jaws.liner + 1e-5));
      }
      // Nothing stands where the physics leaves the opening clear: no cushion or wood over the shelf
      // or the hole.
      for (const Vertex& v : model.body.vertices)
        if (v.position[2] > 1e-4) CHECK(!m.in_throat(Vec3(v.position[0], v.position[1], 0), -1e-5));
      // The pocket's wall below the bed is the hole's edge, and the cup's floor is where the physics
      // leaves a pocketed ball (its bottom kPocketDepth below the bed).
      double floor = 0;
      for (const Vertex& v : model.pockets.vertices) {
        const double d = std::hypot(v.position[0] - m.centre.x(), v.position[1] - m.centre.y());
        if (d > 0.3) continue;
        floor = std::min<double>(floor, v.position[2]);
        if (v.position[2] < -lip - 1e-6) CHECK(d <= m.drop_radius + 1e-5);
      }
      CHECK(floor == doctest::Approx(-kPocketDepth).epsilon(0.01));
    }
  }

  TEST_CASE("the stick may go low over a pocket's opening, not over the wood round its hole") {
    const Scene scene = standard_scene();
    const TableLayout layout = table_layout(scene);
    const PocketMouth& corner = layout.pockets[2];  // the top-right corner
    REQUIRE(corner.cut);
    // The tip 1 cm over the middle of the hole, the stick rising outwards at 45 degrees along the
    // pocket's axis: it clears the wood behind the hole, so only the bed's plane is close.
    CuePose over_hole;
    over_hole.tip = corner.centre + Vec3(0, 0, 0.01 + kCueTipRadius);
    over_hole.axis = Vec3(corner.axis + Vec3(0, 0, 1)).normalized();
    over_hole.visible = true;
    const double tip_low = over_hole.tip.z() - kCueTipRadius * std::sqrt(1 - over_hole.axis.z() * over_hole.axis.z());
    CHECK(stick_clearance(over_hole, scene, {}, 0.028575) == doctest::Approx(tip_low));
    CHECK(tip_low > 0.01);
    // A level stick low over the table's outer corner, behind the hole, meets the wood there.
    CuePose over_corner;
    const double top = layout.rail_top;
    over_corner.tip = Vec3(layout.wood_outer.x1 - 0.04, layout.wood_outer.y1 - 0.04, top - 0.005 + kCueTipRadius);
    over_corner.axis = Vec3(std::sqrt(0.5), std::sqrt(0.5), 0);
    over_corner.visible = true;
    const double wood_gap = stick_clearance(over_corner, scene, {}, 0.028575);
    CHECK(wood_gap < -0.004);
    CHECK(wood_gap > -0.006);
    // Over a facing, below the wood's top, the stick meets the cushion.
    CuePose at_facing = over_hole;
    at_facing.tip = corner.nose[0] + corner.facing[0] * 0.03 - corner.inward[0] * 0.004 + Vec3(0, 0, 0.03);
    CHECK(stick_clearance(at_facing, scene, {}, 0.028575) < 0);
  }
}
