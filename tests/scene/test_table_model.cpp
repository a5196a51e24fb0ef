// One table for every reader: the physics' standard table, the cue stick's clearance, the GL
// preview's meshes and the POV-Ray include all take the cushion, the wood and the sights from
// kStandardTable and table_layout().
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "cue_geometry.h"
#include "pov_format.h"
#include "pov_table.h"
#include "scene.h"
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
    CHECK(rails[0].a.x() == -t.half_length + t.corner_pocket_radius);
    CHECK(pockets[0].radius == t.corner_pocket_radius);
    CHECK(pockets[1].radius == t.side_pocket_radius);
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
    // Just beyond the table's outer edge only the bed's plane is left to clear.
    CHECK(stick_clearance(stick_at(t.rail_reach() + 0.005), scene, {}, 0.028575) ==
          doctest::Approx(z - kCueButtRadius));
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
    // The preview's cushion reaches past the nose end along the facing, to where it meets the wood.
    // (Of the top-left corner's jaws, the top cushion's: its back is the cushion's width along +y.)
    const int top = std::abs(corner.nose[0].y() - kStandardTable.half_width) < 1e-9 ? 0 : 1;
    REQUIRE(corner.nose[top].y() == doctest::Approx(kStandardTable.half_width));
    bool facing_corner = false;
    const Vec3 at_wood =
        corner.nose[top] + corner.facing[top] * (kStandardTable.cushion.width / corner.facing[top].y());
    for (const Vertex& v : model.body.vertices)
      if (std::abs(v.position[0] - at_wood.x()) < 1e-5 && std::abs(v.position[1] - at_wood.y()) < 1e-5)
        facing_corner = true;
    CHECK(facing_corner);
  }
}
