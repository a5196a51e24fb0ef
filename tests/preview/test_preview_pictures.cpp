// billiards-preview's pictures, end to end, for what a user reads in them: the timeline of a run of
// shots shows every shot's stroke, and without --size it is tall enough for the whole event list; in a
// scene of several shots the paths overlay draws the shot in play strongly and the others faint; the
// snapshot's status line never covers the table overlay's labels, at any size.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <imgui.h>
#include <stb_image.h>

#include "builtin_scene.h"
#include "camera_view.h"
#include "files.h"
#include "fonts.h"
#include "headless_canvas.h"
#include "overlays.h"
#include "scene_renderer.h"
#include "shot.h"
#include "support.h"
#include "table.h"
#include "timeline_picture.h"

using namespace bsim;
using bsim::test::quoted;

namespace {

struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

Picture load(const std::string& path) {
  Picture p;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &p.width, &p.height, &channels, 3);
  REQUIRE_MESSAGE(data, "cannot read " << path);
  p.rgb.assign(data, data + static_cast<std::size_t>(p.width) * p.height * 3);
  stbi_image_free(data);
  return p;
}

/// Runs billiards-preview with `args`, which must succeed, and loads the picture it wrote to `out`.
Picture preview(const std::string& args, const std::string& out) {
  const test::CommandResult r =
      test::run_command(quoted(test::bin("billiards-preview")) + " " + args + " -o " + quoted(out));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return load(out);
}

bool near(const unsigned char* c, int r, int g, int b, int tolerance) {
  return std::abs(c[0] - r) <= tolerance && std::abs(c[1] - g) <= tolerance && std::abs(c[2] - b) <= tolerance;
}

/// Pixels in rows [y0, y1) where the two pictures differ by more than `threshold` in some channel.
int strong_changes(const Picture& a, const Picture& b, int y0, int y1, int threshold) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < a.width; ++x) {
      const unsigned char *p = a.at(x, y), *q = b.at(x, y);
      n += std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}) > threshold;
    }
  return n;
}

/// Pixels of a table label's colour: the rails' gold and the pockets' magenta.
int label_pixels(const Picture& p) {
  int n = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) n += near(p.at(x, y), 255, 226, 140, 40) || near(p.at(x, y), 236, 92, 210, 40);
  return n;
}

// Two shots, each rolling one ball a little way over its own half of the table, filmed from straight
// above: ball 0 along the top half in shot 1, ball 1 along the bottom half in shot 2.
const char* const kTwoHalves =
    "ball 0 -0.9  0.35 0.028575  0 0 0  1 0 0 0\n"
    "ball 1  0.9 -0.35 0.028575  0 0 0  1 0 0 0\n"
    "cue 0 0\n"
    "stroke 0.35 0 0 0\n"
    "cue 1 180\n"
    "stroke 0.35 0 0 0\n"
    "camera\nevent 0 0 0 hover  0 0 3.05  0 0 0\nendcamera\n";

// One ball far from the top-right corner, which a camera looks straight down at from 0.5 m.
const char* const kCornerFromAbove =
    "ball 0 -0.6 0 0.028575  0 0 0  1 0 0 0\n"
    "cue 0 180\n"
    "stroke 0.3 0 0 0\n"
    "camera\nevent 0 0 0 hover  1.27 0.62 0.5  1.27 0.62 0\nendcamera\n";

/// The pixel of a width x height picture that plan point p (on the bed) lands on, seen from `pose`.
std::pair<int, int> pixel_at(const CameraPose& pose, const Vec3& p, int width, int height) {
  const CameraView view(pose, kCameraFovDeg, static_cast<double>(width) / height);
  const auto at = view.project(p);
  REQUIRE(at);
  return {static_cast<int>(0.5 * width * (1 + at->x)), static_cast<int>(0.5 * height * (1 - at->y))};
}

/// Cloth: green well above red and blue. Open: dark, not green (the pocket's leather and its shadow).
bool cloth(const unsigned char* c) { return c[1] > c[0] + 25 && c[1] > c[2] + 10; }
bool open(const unsigned char* c) { return std::max({c[0], c[1], c[2]}) < 90 && c[1] < c[0] + 15; }

}  // namespace

TEST_SUITE("preview pictures") {
  TEST_CASE("from above, a corner pocket is open where the physics drops a ball and cloth on its shelf") {
    test::TempDir dir;
    const std::string scene = dir.file("corner.scn", kCornerFromAbove);
    const Picture p = preview(quoted(scene) + " --at 0 --size 640x360", (dir.path / "corner.png").string());
    const auto loaded = load_shot(kCornerFromAbove, "corner");
    REQUIRE(loaded.scripted());
    const TableLayout layout = table_layout(loaded.shot->scene);
    const PocketMouth& m = layout.pockets[2];
    REQUIRE(m.cut);
    const CameraPose pose{Vec3(1.27, 0.62, 0.5), Vec3(1.27, 0.62, 0), false};
    const auto colour = [&](const Vec3& at) {
      const auto [x, y] = pixel_at(pose, at, p.width, p.height);
      return p.at(x, y);
    };
    const auto rgb = [](const unsigned char* c) {
      return std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]);
    };
    // The physics' hole, round: open 4 mm inside its edge all round, and in its middle.
    CHECK_MESSAGE(open(colour(m.centre)), rgb(colour(m.centre)));
    for (int k = 0; k < 16; ++k) {
      const double a = 2 * 3.14159265358979323846 * k / 16;
      const Vec3 inside = m.centre + (m.drop_radius - 0.004) * Vec3(std::cos(a), std::sin(a), 0);
      CAPTURE(k);
      CHECK_MESSAGE(open(colour(inside)), rgb(colour(inside)));
    }
    // The shelf before the hole, between the facings, where a ball's centre stays on the table: cloth,
    // up to 4 mm from the hole's rounded lip.
    const Vec3 middle = (m.nose[0] + m.nose[1]) / 2;
    for (const Vec3& at : {Vec3(middle + m.axis * 0.01), Vec3(middle + m.axis * (m.shelf() / 2)),
                           Vec3(m.centre - m.axis * (m.drop_radius + kStandardTable.jaws.lip_round + 0.004))})
      CHECK_MESSAGE(cloth(colour(at)), rgb(colour(at)));
  }

  TEST_CASE("the timeline of scenes/runout.scn shows each of its seven shots' strokes") {
    test::TempDir dir;
    const Picture t =
        preview(quoted(test::source_path("scenes/runout.scn").string()) + " --timeline", (dir.path / "t.png").string());
    // The stroke diagrams' tip dots (chalk blue) in the band of shots: one cluster per shot.
    std::vector<bool> blue(static_cast<std::size_t>(t.width), false);
    for (int y = 0; y < t.height / 4; ++y)
      for (int x = 0; x < t.width; ++x)
        if (near(t.at(x, y), 30, 90, 220, 20)) blue[static_cast<std::size_t>(x)] = true;
    int clusters = 0;
    for (std::size_t x = 0; x < blue.size(); ++x) clusters += blue[x] && (x == 0 || !blue[x - 1]);
    CHECK(clusters == 7);
  }

  TEST_CASE("without --size the timeline is tall enough to list every event (the built-in break)") {
    const ShotResult loaded = load_shot(builtin_scene_text(), "break");
    REQUIRE(loaded.scripted());
    ImFontAtlas atlas;
    const UiFonts fonts = add_ui_fonts(atlas, 16);
    atlas.Build();
    const float needed = timeline_height(timeline_data(*loaded.shot), fonts, 1600);
    test::TempDir dir;
    const Picture t = preview("--timeline", (dir.path / "t.png").string());
    CHECK(t.width == 1600);
    CHECK(t.height >= needed);
  }

  TEST_CASE("the paths overlay in a scene of several shots: the shot in play strong, the others faint") {
    test::TempDir dir;
    const std::string scene = dir.file("halves.scn", kTwoHalves);
    const ShotResult loaded = load_shot(kTwoHalves, "halves");
    REQUIRE(loaded.scripted());
    const Timeline& timeline = loaded.shot->timeline;
    REQUIRE(timeline.shot_count() == 2);
    // The end of shot 1 (ball 0 has rolled) and the end of the scene (ball 1 has rolled too).
    const double first = timeline.shots()[1].start - 0.05, last = timeline.duration();
    const auto pair = [&](double t, const char* name) {
      const std::string at = " --size 1280x720 --at " + std::to_string(t);
      return std::pair{
          preview(quoted(scene) + at, (dir.path / (std::string(name) + "_plain.png")).string()),
          preview(quoted(scene) + at + " --overlay paths", (dir.path / (std::string(name) + ".png")).string())};
    };
    const auto [plain1, paths1] = pair(first, "first");
    const auto [plain2, paths2] = pair(last, "last");
    // Above and below the middle, leaving out the status line along the bottom.
    const int middle = 360, low = 640, strong = 80;
    const int ball0_then = strong_changes(plain1, paths1, 0, middle, strong);
    REQUIRE(ball0_then > 200);  // shot 1's path drawn strongly while it is in play
    CHECK(strong_changes(plain1, paths1, middle, low, strong) < ball0_then / 10);
    const int ball1_now = strong_changes(plain2, paths2, middle, low, strong);
    CHECK(ball1_now > 200);                                                      // shot 2's path strong now
    CHECK(strong_changes(plain2, paths2, 0, middle, strong) < ball0_then / 10);  // shot 1's faint
  }

  TEST_CASE("the status line never covers the table's labels, at 640x360 or 320x180") {
    const std::string scene = test::source_path("scenes/numbering.scn").string();
    const ShotResult loaded = load_shot(test::require_file(scene), "numbering");
    REQUIRE(loaded.scripted());
    test::TempDir dir;
    for (const auto& size : {std::pair{640, 360}, std::pair{320, 180}}) {
      const int w = size.first, h = size.second;  // plain names: clang cannot capture a binding
      CAPTURE(w);
      // The labels alone, drawn as the snapshot draws them but with no status line.
      HeadlessCanvas canvas;
      SceneRenderer renderer;
      std::string error;
      const float text_px = std::clamp(static_cast<float>(h) / 720.f * 17.f, 11.f, 34.f);  // as the snapshots
      REQUIRE_MESSAGE(canvas.open(w, h, text_px, error), error);
      REQUIRE_MESSAGE(renderer.init(error), error);
      renderer.set_multisampling(4);
      renderer.set_scene(loaded.shot->scene);
      const FrameState frame = scripted_frame(*loaded.shot, 0.0);
      renderer.draw(loaded.shot->scene, frame, w, h);
      ImDrawList* list = canvas.begin_2d();
      draw_table_numbering(*list, OverlayFrame{*loaded.shot, 0.0, frame.camera, double(w), double(h), canvas.fonts()});
      canvas.end_2d();
      const std::string alone = (dir.path / "alone.png").string();
      REQUIRE_MESSAGE(canvas.write_png(alone, error), error);
      const Picture labels = load(alone);
      const int expected = label_pixels(labels);
      REQUIRE(expected > 50);
      // Every label whole inside the picture: none runs off an edge (at 320x180 the corner pockets'
      // two-line labels reach past the sides unless they slide inwards).
      Picture edges = labels;
      for (int y = 0; y < edges.height; ++y)
        for (int x = 3; x < edges.width - 3; ++x)
          if (y >= 2 && y < edges.height - 2) std::fill_n(&edges.rgb[(static_cast<std::size_t>(y) * w + x) * 3], 3, 0);
      CHECK_MESSAGE(label_pixels(edges) == 0, label_pixels(edges) << " label pixels at the picture's edge");
      // The snapshot, status line and all: every label as legible as alone (a label moved clear of the
      // status line may land a fraction of a pixel otherwise, hence the small tolerance; a covered
      // bottom row at 320x180 loses a third).
      const Picture snapshot =
          preview(quoted(scene) + " --at 0 --overlay table --size " + std::to_string(w) + "x" + std::to_string(h),
                  (dir.path / "snapshot.png").string());
      CHECK_MESSAGE(label_pixels(snapshot) >= expected * 0.95, label_pixels(snapshot) << " of " << expected);
    }
  }
}
