// The look's light and cloth (README "Light, motion blur and the look before and after"): the cloth
// brightens and pales towards grazing views by Lommel-Seeliger's law, the room comes out 2 to 3.5
// stops under the lit cloth, every light but the lamp is shadowless, and the pockets' fill lights
// only their leather. Rendered by POV-Ray at small sizes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "builtin_scene.h"
#include "develop.h"
#include "files.h"
#include "look_regions.h"
#include "pov_format.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

std::string include_text(const Shot& shot) {
  std::ostringstream out;
  write_pov_include(shot.scene, Quality::final, out);
  return out.str();
}

/// Renders `pov` (a file in `dir`, beside the include) at width x height with `options` and reads
/// back the linear light POV-Ray wrote.
HdrImage render(const fs::path& dir, const std::string& pov, int width, int height, const std::string& options) {
  const test::CommandResult r =
      test::run_command("cd " + quoted(dir.string()) + " && povray -D +FH +WT1 +I" + pov + " +Oout.hdr +W" +
                        std::to_string(width) + " +H" + std::to_string(height) + " " + options + " 2>&1");
  REQUIRE_MESSAGE(r.exit_code == 0, r.out);
  HdrImage picture;
  std::string error;
  REQUIRE_MESSAGE(read_hdr((dir / "out.hdr").string(), picture, error), error);
  return picture;
}

/// The blocks of `text` that open with `opening` ("light_group {"), each up to its closing brace.
std::vector<std::string> blocks(const std::string& text, const std::string& opening) {
  std::vector<std::string> found;
  for (std::size_t at = text.find(opening); at != std::string::npos; at = text.find(opening, at + 1)) {
    int depth = 0;
    std::size_t end = at;
    for (; end < text.size(); ++end) {
      if (text[end] == '{') ++depth;
      if (text[end] == '}' && --depth == 0) break;
    }
    found.push_back(text.substr(at, end + 1 - at));
  }
  return found;
}

/// `text` without the body of macro `name` (from its #macro line to the #end closing it).
std::string without_macro(std::string text, const std::string& name) {
  const std::size_t at = text.find("#macro " + name + "(");
  REQUIRE(at != std::string::npos);
  int depth = 0;
  std::size_t line = at;
  while (line < text.size()) {
    const std::size_t next = text.find('\n', line);
    const std::string l = text.substr(line, next - line);
    const std::size_t first = l.find_first_not_of(' ');
    const std::string directive = first == std::string::npos ? "" : l.substr(first);
    for (const char* open : {"#macro", "#if", "#for", "#while", "#switch", "#ifdef", "#ifndef"})
      if (directive.rfind(open, 0) == 0) ++depth;
    if (directive.rfind("#end", 0) == 0 && --depth == 0) return text.erase(at, next - at);
    line = next + 1;
  }
  FAIL("macro " << name << " has no #end");
  return text;
}

double luma(const HdrImage& p, int x, int y) {
  const std::size_t i =
      3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(p.width) + static_cast<std::size_t>(x));
  return 0.2126 * p.rgb[i] + 0.7152 * p.rgb[i + 1] + 0.0722 * p.rgb[i + 2];
}

/// How far the colour of pixel (x, y) is from grey: (max - min) / max of its channels.
double saturation(const HdrImage& p, int x, int y) {
  const std::size_t i =
      3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(p.width) + static_cast<std::size_t>(x));
  const float hi = std::max({p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]}),
              lo = std::min({p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]});
  return hi > 0 ? (hi - lo) / hi : 0;
}

}  // namespace

TEST_SUITE("look") {
  TEST_CASE("the cloth's colour brightens towards grazing views as 2 / (1 + cos o) and pales") {
    test::require_program("povray");
    const auto shot = test::load_scene(builtin_scene_text(), "break");
    test::TempDir dir;
    REQUIRE(test::write_file(dir.path / std::string(kPovIncludeName), include_text(*shot)));
    // The cloth's pigment alone (lit by nothing, shown as it is) at one point of the bed away from
    // the wear, the chalk and the ball marks, seen from 0.9 m at each angle o from the normal: the
    // middle pixel of a 3 x 3 picture without antialiasing is the ray through the picture's middle.
    const Vec3 at(0.2, 0.1, 0);
    double head_on = 0, head_on_saturation = 0;
    for (const double degrees : {0.0, 30.0, 45.0, 60.0, 70.0, 80.0, 87.0}) {
      CAPTURE(degrees);
      const double o = degrees * std::numbers::pi / 180;
      const Vec3 eye = at + 0.9 * Vec3(-std::sin(o), 0, std::cos(o));
      std::ostringstream pov;
      pov << "#version 3.7;\n#include \"" << kPovIncludeName
          << "\"\n"
          // (Straight down, the look point moves a hair along y: POV-Ray cannot look along its sky.)
          << "camera { location " << pov_vector(eye) << " sky z up z right -x angle 10 look_at "
          << pov_vector(at + Vec3(0, degrees == 0 ? 1e-4 : 0, 0)) << " }\n"
          << "plane { z, 0 texture { pigment { P_Cloth } finish { emission 1 diffuse 0 } } no_shadow }\n";
      REQUIRE(test::write_file(dir.path / "probe.pov", pov.str()));
      const HdrImage p = render(dir.path, "probe.pov", 3, 3, "-A");
      if (degrees == 0) {
        head_on = luma(p, 1, 1), head_on_saturation = saturation(p, 1, 1);
        REQUIRE(head_on > 0);
        continue;
      }
      // The colour map follows the law in steps of 9 degrees: within 2 % between them.
      CHECK(luma(p, 1, 1) / head_on == doctest::Approx(2 / (1 + std::cos(o))).epsilon(0.02));
      // Paler from 45 degrees on: a quarter of the way to grey at grazing.
      if (degrees > 50) CHECK(saturation(p, 1, 1) < head_on_saturation - 0.02);
    }
  }

  TEST_CASE("the built-in break's wide shot: the walls and the floor 2 to 3.5 stops under the lit cloth") {
    test::require_program("povray");
    const auto shot = test::load_scene(builtin_scene_text(), "break");
    test::TempDir dir;
    REQUIRE(test::write_file(dir.path / std::string(kPovIncludeName), include_text(*shot)));
    const int frame = 150, width = 320, height = 180;
    std::ostringstream pov;
    write_pov_frame(*shot, frame, 30, pov);
    REQUIRE(test::write_file(dir.path / "wide.pov", pov.str()));
    const HdrImage p = render(dir.path, "wide.pov", width, height, "+Q9 +A0.3 +AM2 +R2");
    const test::LookLuma l =
        test::look_luma(shot->scene, frame_content(*shot, frame, 30).camera_pose, width, height, p.rgb);
    // The camera sees enough of each.
    REQUIRE(l.cloth_pixels > 1000);
    REQUIRE(l.wall_pixels > 1000);
    REQUIRE(l.floor_pixels > 1000);
    const double wall = std::log2(l.cloth / l.wall), floor = std::log2(l.cloth / l.floor);
    CAPTURE(wall);
    CAPTURE(floor);
    CHECK(wall >= 2.0);
    CHECK(wall <= 3.5);
    CHECK(floor >= 2.0);
    CHECK(floor <= 3.5);
  }

  TEST_CASE("every light but the lamp casts no shadow; the pockets' fill and the hall's fill light only their groups") {
    const auto shot = test::load_scene(builtin_scene_text(), "break");
    const std::string include = include_text(*shot);
    // The lamp (the LampLight macro) is the one light that tests shadows.
    const std::string others = without_macro(include, "LampLight");
    const std::vector<std::string> lights = blocks(others, "light_source {");
    CHECK(lights.size() >= 6);
    for (const std::string& light : lights) {
      CAPTURE(light);
      CHECK(light.find("shadowless") != std::string::npos);
    }
    // The pockets' fill is in one light group, whose only object is the leather (the liners, the
    // cups and the beads).
    int fills = 0;
    for (const std::string& group : blocks(include, "light_group {")) {
      const bool fill = group.find("PocketFillColour") != std::string::npos;
      fills += fill;
      if (!fill) continue;
      CHECK(blocks(group, "object {").size() == 1);
      CHECK(group.find("object { Liners }") != std::string::npos);
    }
    CHECK(fills == 1);
    CHECK(blocks(include, "light_source {").size() > lights.size());  // the lamp's own
    // Outside a light group nothing is lit by the pockets' fill or the hall's.
    std::string outside = include;
    for (const std::string& group : blocks(include, "light_group {")) outside.erase(outside.find(group), group.size());
    outside = without_macro(outside, "HallFill");
    for (const std::string& light : blocks(outside, "light_source {"))
      CHECK(light.find("PocketFillColour") == std::string::npos);
    CHECK(outside.find("HallFill(") == std::string::npos);
    // The cloth, the cushions and the balls are lit by the lamp and the global lights alone.
    for (const std::string& group : blocks(include, "light_group {")) {
      if (group.find("object { TablePlay }") == std::string::npos) continue;
      CHECK(blocks(group, "light_source {").empty());
      CHECK(group.find("HallFill(") == std::string::npos);
    }
    std::ostringstream frame;
    write_pov_frame(*shot, 0, 30, frame);
    for (const std::string& group : blocks(frame.str(), "light_group {"))
      CHECK(group.find("HallFill") == std::string::npos);
  }

  TEST_CASE("each frame declares the camera's place before the include: the weave fades with distance from it") {
    const auto shot = test::load_scene(builtin_scene_text(), "break");
    for (const int frame : {0, 150}) {
      std::ostringstream out;
      write_pov_frame(*shot, frame, 30, out);
      const std::string text = out.str();
      const FrameContent content = frame_content(*shot, frame, 30);
      const std::string declared = "#declare CamPos = " + pov_vector(content.camera_pose.location) + ";";
      CHECK(text.find(declared) != std::string::npos);
      CHECK(text.find(declared) < text.find("#include"));
      CHECK(text.find("location " + pov_vector(content.camera_pose.location)) != std::string::npos);
    }
    CHECK(include_text(*shot).find("translate CamPos") != std::string::npos);
  }
}
