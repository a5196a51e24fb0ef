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
  out << "#declare ShadeTaper = " << pov_number(lamp.taper) << ";  // m the shade's sides are drawn in, rim to eaves\n";
  out << "#declare RoofPitch = " << pov_number(lamp.roof_pitch_deg) << ";  // deg: the hipped roof over the eaves\n";
  out << "#declare LampHotspot = " << pov_number(lamp.hotspot_deg) << ";  // deg from straight down: the light's\n";
  out << "#declare LampFalloff = " << pov_number(lamp.falloff_deg) << ";  // full cone and where it fades out\n";
  out << "#declare PocketLinerT = " << pov_number(spec.jaws.liner) << ";  // the pockets' leather liner\n";
  out << "#declare PocketLipR = " << pov_number(spec.jaws.lip_round)
      << ";  // the slate's rounded edge under the cloth, round the drop circle\n";
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

void write_pov_include(const Scene& scene, Quality quality, std::ostream& out) {
  out << "// Billiards Sim: the table, balls, cue stick, room and lights shared by every frame.\n"
         "// Units are metres, z is up, the bed is z = 0 and the table's middle is the origin.\n\n"
         "// ---- from the scene\n";
  out << "#declare Final = " << (quality == Quality::final ? 1 : 0)
      << ";  // area light (final) or point lights (draft)\n";
  out << "#declare BallR = " << pov_number(scene.physics.ball_radius) << ";\n";
  out << "#declare PocketDepth = " << pov_number(kPocketDepth) << ";  // how far below the bed a pocketed ball rests\n";

  // Without cushions the layout is the standard bed: a bare bed around the pockets.
  const TableLayout layout = table_layout(scene);
  const TableRect& noses = layout.noses;

  out << "#declare NoseMin = " << pov_vector2(noses.x0, noses.y0) << ";\n";
  out << "#declare NoseMax = " << pov_vector2(noses.x1, noses.y1) << ";\n";
  out << "#declare RailCount = " << scene.rails.size() << ";\n";
  if (!scene.rails.empty()) {
    write_array(out, "RailA", scene.rails, [](const Rail& r) { return pov_vector2(r.a.x(), r.a.y()); });
    write_array(out, "RailB", scene.rails, [](const Rail& r) { return pov_vector2(r.b.x(), r.b.y()); });
    write_array(out, "RailH", scene.rails, [](const Rail& r) { return pov_number(r.a.z()); });
    // How each cushion end is cut: -1 square, else how far its jaw's facing runs on past the nose
    // end per metre behind the nose.
    const auto slant = [](const CushionEnd& e) { return pov_number(e.pocket < 0 ? -1.0 : e.slant); };
    write_array(out, "RailSlantA", layout.ends_a, slant);
    write_array(out, "RailSlantB", layout.ends_b, slant);
  }
  out << "#declare PocketCount = " << scene.pockets.size() << ";\n";
  if (!scene.pockets.empty()) {
    const std::vector<PocketMouth>& m = layout.pockets;
    const auto v2 = [](const Vec3& p) { return pov_vector2(p.x(), p.y()); };
    write_array(out, "PocketC", scene.pockets, [](const Pocket& p) { return pov_vector2(p.center.x(), p.center.y()); });
    write_array(out, "PocketR", scene.pockets, [](const Pocket& p) { return pov_number(p.radius); });
    write_array(out, "PocketJawed", m, [](const PocketMouth& p) { return p.jawed() ? "1" : "0"; });
    // A cut pocket's jaws are the physics' own: the shelf between the facings, the hole behind it and
    // each jaw point's rounding (its centre and where it meets the nose and the facing).
    write_array(out, "PocketCut", m, [](const PocketMouth& p) { return p.cut ? "1" : "0"; });
    write_array(out, "JawRoundR", m, [](const PocketMouth& p) { return pov_number(p.round_radius); });
    write_array(out, "JawRoundC0", m, [&](const PocketMouth& p) { return v2(p.round_centre[0]); });
    write_array(out, "JawRoundC1", m, [&](const PocketMouth& p) { return v2(p.round_centre[1]); });
    write_array(out, "JawNoseEnd0", m, [&](const PocketMouth& p) { return v2(p.nose_end[0]); });
    write_array(out, "JawNoseEnd1", m, [&](const PocketMouth& p) { return v2(p.nose_end[1]); });
    write_array(out, "JawFaceStart0", m, [&](const PocketMouth& p) { return v2(p.face_start[0]); });
    write_array(out, "JawFaceStart1", m, [&](const PocketMouth& p) { return v2(p.face_start[1]); });
    write_array(out, "JawNose0", m, [&](const PocketMouth& p) { return v2(p.nose[0]); });
    write_array(out, "JawNose1", m, [&](const PocketMouth& p) { return v2(p.nose[1]); });
    write_array(out, "JawIn0", m, [&](const PocketMouth& p) { return v2(p.inward[0]); });
    write_array(out, "JawIn1", m, [&](const PocketMouth& p) { return v2(p.inward[1]); });
    write_array(out, "PocketAxis", m, [&](const PocketMouth& p) { return v2(p.axis); });
    write_array(out, "ThroatC", m, [&](const PocketMouth& p) { return v2(p.throat_centre); });
    write_array(out, "ThroatR", m, [](const PocketMouth& p) { return pov_number(p.throat_radius); });
    write_array(out, "ThroatT0", m, [&](const PocketMouth& p) { return v2(p.tangent[0]); });
    write_array(out, "ThroatT1", m, [&](const PocketMouth& p) { return v2(p.tangent[1]); });
  }
  write_table_description(layout, out);
  write_ball_colours(out);
  out << "\n" << pov_models_text();
}

}  // namespace bsim
