// Golden pictures of the preview: a frame of a made-up table (a rack, turned balls, the stick) and a
// made-up timeline (also with a camera script that does not fit it), drawn in-process and compared
// with tests/golden/preview/*.png within a tolerance.
// The inputs are built here, not simulated, so only a change to the drawing moves the pictures.
//
// Regenerate after an intended change to the drawing (then look at the new pictures before committing):
//   BSIM_UPDATE_GOLDENS=1 build/bin/bsim_tests
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <imgui.h>
#include <stb_image.h>

#include "files.h"
#include "golden.h"
#include "headless_canvas.h"
#include "overlays.h"
#include "png_writer.h"
#include "scene_renderer.h"
#include "shot.h"
#include "stroke_diagram.h"
#include "support.h"
#include "timeline_picture.h"
#include "view.h"

using namespace bsim;

namespace {

Scene rack_scene() {
  Scene scene;
  scene.name = "golden";
  scene.rails = standard_rails();
  scene.pockets = standard_pockets();
  const double r = scene.physics.ball_radius, d = 2 * r + 0.0005;
  const int order[15] = {1, 9, 2, 10, 8, 3, 11, 7, 14, 4, 5, 13, 15, 6, 12};
  scene.balls.push_back(Ball{0, Vec3(0.0, -0.1, r), Vec3::Zero(), Vec3::Zero(), Quat::Identity(), {}});
  int k = 0;
  for (int row = 0; row < 5; ++row)
    for (int j = 0; j <= row; ++j) {
      // Turn every ball differently so stripes and numbers show at many angles.
      const Quat turn(Eigen::AngleAxisd(0.35 * k, Vec3(std::cos(k), std::sin(k), 0.4).normalized()));
      scene.balls.push_back(Ball{order[k],
                                 Vec3(0.45 + row * d * std::sqrt(3.0) / 2, (j - row / 2.0) * d, r),
                                 Vec3::Zero(),
                                 Vec3::Zero(),
                                 turn,
                                 {}});
      ++k;
    }
  return scene;
}

FrameState rack_frame(const Scene& scene) {
  FrameState frame;
  for (const Ball& b : scene.balls)
    frame.balls.push_back(BallState{b.position, Vec3::Zero(), Vec3::Zero(), b.orientation, Motion::stationary});
  frame.cue.visible = true;
  frame.cue.tip = Vec3(-0.035, -0.108, 0.03);
  frame.cue.axis = Vec3(-1, -0.2, 0.12).normalized();
  frame.camera.eye = Vec3(-0.42, -0.55, 0.36);
  frame.camera.target = Vec3(0.42, 0.0, 0.0);
  return frame;
}

TimelineData made_up_timeline() {
  TimelineData data;
  data.title = "golden  \xE2\x80\x94  6.00 s, 8 events (0 to 7), 1 pocketed";
  data.duration = 6.0;
  const std::pair<double, EventType> events[] = {{0.0, EventType::start},     {2.5, EventType::cue},
                                                 {2.9, EventType::ball_ball}, {3.05, EventType::ball_rail},
                                                 {3.1, EventType::ball_ball}, {3.6, EventType::ball_rail},
                                                 {4.4, EventType::ball_rail}, {6.0, EventType::end}};
  int index = 0;
  for (const auto& [time, type] : events) data.events.push_back({index++, time, type, "made-up event"});
  data.drops.push_back({4.9, 3, 2, pocket_name(standard_pockets(), 2)});
  data.painted = {0, 1, 9, 12};  // ball 3 is the 12, ball 2 the 9
  // The last description too short for its label, which goes under the bars.
  data.camera = {{0.0, 2.5, 0, CameraMode::hover, "hover", "", true, ""},
                 {2.5, 3.1, 1, CameraMode::follow, "follow ball 0", "", true, "cue"},
                 {3.1, 4.9, 4, CameraMode::look, "look ball 3 (12)", "", true, "hit 0 3"},
                 {4.9, 5.85, 0, CameraMode::hover, "hover", "", true, "drop 3"},
                 {5.85, 6.0, 0, CameraMode::follow, "follow ball 2 (9)", "", true, "at 5.85"}};
  data.windows = {{1.75, 2.5, 2.68}, {2.9, 3.1, 3.9}, {4.6, 4.9, 5.2}, {5.7, 5.85, 5.9}};
  data.cue = {{CuePhase::approach, 0.0, 0.9},
              {CuePhase::preflight, 0.9, 2.25},
              {CuePhase::impact, 2.25, 2.6},
              {CuePhase::retraction, 2.6, 3.3}};
  return data;
}

// The same shot with a camera script that does not fit it, as unscripted_timeline_data lays it out:
// a description listed out of order, one naming an event the shot lacks, and the errors as printed.
TimelineData made_up_failed_script() {
  TimelineData data = made_up_timeline();
  data.windows.clear();
  data.cue.clear();
  data.camera = {{0.0, 2.9, 0, CameraMode::hover, "hover", "", true, ""},
                 {4.4, 6.0, 6, CameraMode::follow, "follow ball 0", "", true, ""},
                 {2.9, 4.4, 2, CameraMode::look, "look ball 3",
                  "event 2 is listed after event 6: list the camera's events in increasing order", true, ""},
                 {6.0, 6.0, 9, CameraMode::follow, "follow ball 1",
                  "no such event \xE2\x80\x94 the shot has 8 (0 to 7)", false, ""}};
  data.script_errors = {
      "golden.scn:9:7: error: event 2 is listed after event 6: list the camera's events in increasing order",
      "golden.scn:10:7: error: event 9 does not exist: the shot has 8 events (0 to 7)"};
  return data;
}

// A scene of three shots: the made-up shot above played three times, 6 s apart, each with its stroke
// (draw, follow, right english), as timeline_data lays out a scene of several shots.
TimelineData made_up_three_shots() {
  TimelineData data = made_up_timeline();
  data.title = "golden  \xE2\x80\x94  18.00 s, 20 events (0 to 19), 3 pocketed, 3 shots";
  data.duration = 18.0;
  const TimelineData one = made_up_timeline();
  data.events.clear();
  data.drops.clear();
  data.camera.clear();
  data.windows.clear();
  data.cue.clear();
  int index = 0;
  const char* strokes[] = {"0 -0.2", "0 0.2", "0.2 0"};
  for (int k = 0; k < 3; ++k) {
    const double t0 = 6.0 * k;
    for (const TimelineEventMark& e : one.events) {
      if ((e.type == EventType::start && k > 0) || (e.type == EventType::end && k < 2)) continue;
      data.events.push_back({index++, t0 + e.time, e.type, e.label});
    }
    data.drops.push_back({t0 + 4.9, 1 + k, 2, pocket_name(standard_pockets(), 2)});
    // The first shot filmed as the one-shot picture films it, the later ones by one description each.
    for (const TimelineCameraSpan& c : one.camera)
      if (k == 0) data.camera.push_back(c);
    if (k > 0)
      data.camera.push_back(
          {t0, t0 + 6.0, 0, CameraMode::follow, "follow ball 0", "", true, "shot " + std::to_string(k + 1) + " start"});
    if (k == 0) data.windows = one.windows;
    for (const CuePhaseSpan& p : one.cue) data.cue.push_back({p.phase, t0 + p.begin, t0 + p.end});
    TimelineShotSection section;
    section.start = t0;
    section.cue = t0 + 2.5;
    section.end = t0 + 6.0;
    section.label = "shot " + std::to_string(k + 1);
    section.detail = "cue 0 pot " + std::to_string(k + 1) + " into top-right corner at 12.5\xC2\xB0\nstrike at " +
                     std::to_string(static_cast<int>(t0 + 2.5)) + ".50 s";
    Stroke stroke;
    stroke.speed = 2.0;
    std::sscanf(strokes[k], "%lf %lf", &stroke.side, &stroke.height);
    section.stroke = stroke;
    data.shots.push_back(section);
  }
  return data;
}

struct Comparison {
  double mean = 0;      ///< mean absolute difference per channel, 0-255
  double outliers = 0;  ///< fraction of pixels with a channel off by more than kOutlier
};
constexpr int kOutlier = 48;
// Another compiler or Mesa build may move edges by a pixel and shading by a level or two.
constexpr double kMaxMean = 2.0;
constexpr double kMaxOutliers = 0.01;

Comparison compare(const std::vector<std::uint8_t>& rgba_bottom_up, int width, int height, const std::string& golden) {
  int w = 0, h = 0, channels = 0;
  unsigned char* expected = stbi_load(golden.c_str(), &w, &h, &channels, 3);
  REQUIRE_MESSAGE(expected, test::missing_golden_message(golden));
  REQUIRE(w == width);
  REQUIRE(h == height);
  Comparison c;
  long long total = 0, outliers = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* got = &rgba_bottom_up[(static_cast<std::size_t>(height - 1 - y) * width + x) * 4];
      const unsigned char* want = &expected[(static_cast<std::size_t>(y) * width + x) * 3];
      int worst = 0;
      for (int k = 0; k < 3; ++k) {
        const int d = std::abs(int(got[k]) - int(want[k]));
        total += d;
        worst = std::max(worst, d);
      }
      outliers += worst > kOutlier;
    }
  stbi_image_free(expected);
  c.mean = static_cast<double>(total) / (3.0 * width * height);
  c.outliers = static_cast<double>(outliers) / (static_cast<double>(width) * height);
  return c;
}

bool within_tolerance(const Comparison& c) { return c.mean <= kMaxMean && c.outliers <= kMaxOutliers; }

/// Whether the golden picture exists, has the canvas's size and the drawing matches it within the tolerance.
bool golden_still_fits(HeadlessCanvas& canvas, const std::string& golden) {
  int w = 0, h = 0, channels = 0;
  if (!std::filesystem::exists(golden) || !stbi_info(golden.c_str(), &w, &h, &channels)) return false;
  if (w != canvas.width() || h != canvas.height()) return false;
  return within_tolerance(compare(canvas.pixels(), canvas.width(), canvas.height(), golden));
}

void check_against_golden(HeadlessCanvas& canvas, const std::string& name) {
  const std::string golden = test::golden_path("preview", name).string();
  std::string error;
  if (test::updating_goldens() && !golden_still_fits(canvas, golden)) {
    // Replaced only when the drawing no longer fits it, so regenerating everything leaves alone the
    // pictures whose pixels moved only by the rasteriser's rounding, within the tolerance.
    test::TempDir dir;
    const std::string drawn = (dir.path / name).string();
    REQUIRE_MESSAGE(canvas.write_png(drawn, error), error);
    test::write_golden(golden, test::require_file(drawn));
  }
  const Comparison c = compare(canvas.pixels(), canvas.width(), canvas.height(), golden);
  if (!within_tolerance(c)) {
    const std::string actual = (std::filesystem::temp_directory_path() / ("actual-" + name)).string();
    canvas.write_png(actual, error);
    FAIL_CHECK(name << " differs from its golden picture (mean difference " << c.mean << ", " << c.outliers * 100
                    << "% of pixels far off); this run drew " << actual);
  }
}

/// Draws `shot` at its start as the snapshots do, 960x540 with 4x multisampling, into `canvas`
/// (opened here); returns the frame drawn, for the overlays on top.
FrameState draw_shot_start(HeadlessCanvas& canvas, const Shot& shot) {
  SceneRenderer renderer;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(960, 540, 14, error), error);
  REQUIRE_MESSAGE(renderer.init(error), error);
  renderer.set_multisampling(4);
  renderer.set_scene(shot.scene);
  const FrameState frame = scripted_frame(shot, 0.0);
  renderer.draw(shot.scene, frame, 960, 540);
  return frame;
}

}  // namespace

TEST_SUITE("preview golden pictures") {
  TEST_CASE("a frame: table, pockets, numbered and striped balls turned every way, the stick, shadows") {
    HeadlessCanvas canvas;
    SceneRenderer renderer;
    std::string error;
    REQUIRE_MESSAGE(canvas.open(480, 270, 13, error), error);
    REQUIRE_MESSAGE(renderer.init(error), error);
    const Scene scene = rack_scene();
    renderer.set_multisampling(4);
    renderer.set_scene(scene);
    renderer.draw(scene, rack_frame(scene), 480, 270);
    check_against_golden(canvas, "frame.png");
  }

  TEST_CASE("the timeline: event marks and numbers, a pocket drop, camera spans, windows, cue phases, the list") {
    HeadlessCanvas canvas;
    std::string error;
    REQUIRE_MESSAGE(canvas.open(800, 300, 14, error), error);
    ImDrawList* list = canvas.begin_2d();
    draw_timeline(*list, made_up_timeline(), canvas.fonts(), {0, 0, 800, 300});
    canvas.end_2d();
    check_against_golden(canvas, "timeline.png");
  }

  TEST_CASE("the timeline of three shots: a labelled section per shot with its stroke, separators through the rows") {
    HeadlessCanvas canvas;
    std::string error;
    REQUIRE_MESSAGE(canvas.open(1200, 400, 14, error), error);
    ImDrawList* list = canvas.begin_2d();
    draw_timeline(*list, made_up_three_shots(), canvas.fonts(), {0, 0, 1200, 400});
    canvas.end_2d();
    check_against_golden(canvas, "timeline_shots.png");
  }

  TEST_CASE("the timeline data of tests/scene/three_shots.scn: a section per shot over its span; one shot: none") {
    const ShotResult three = load_shot(test::require_file(test::source_path("tests/scene/three_shots.scn")), "three");
    REQUIRE(three.shot);
    const TimelineData data = timeline_data(*three.shot);
    const std::vector<ShotSpan>& spans = three.shot->timeline.shots();
    REQUIRE(spans.size() == 3);
    REQUIRE(data.shots.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(data.shots[k].label == "shot " + std::to_string(k + 1));
      CHECK(data.shots[k].start == spans[k].start);
      CHECK(data.shots[k].cue == spans[k].cue);
      CHECK(data.shots[k].end == (k < 2 ? spans[k + 1].start : three.shot->timeline.duration()));
      REQUIRE(data.shots[k].stroke);
      CHECK(data.shots[k].stroke->speed == three.shot->scene.cues[k].stroke->speed);
      CHECK(data.shots[k].stroke->side == three.shot->scene.cues[k].stroke->side);
      CHECK(data.shots[k].stroke->height == three.shot->scene.cues[k].stroke->height);
    }
    CHECK_FALSE(data.stroke);  // each shot's stroke is in its section, none in the title
    CHECK(data.title.find("3 shots") != std::string::npos);
    const ShotResult one = load_shot(test::require_file(test::source_path("scenes/pot_corner.scn")), "pot_corner");
    REQUIRE(one.shot);
    CHECK(timeline_data(*one.shot).shots.empty());
  }

  TEST_CASE("a timeline whose camera script does not fit: the script as written, faults in red, the errors") {
    HeadlessCanvas canvas;
    std::string error;
    REQUIRE_MESSAGE(canvas.open(800, 360, 14, error), error);
    ImDrawList* list = canvas.begin_2d();
    draw_timeline(*list, made_up_failed_script(), canvas.fonts(), {0, 0, 800, 360});
    canvas.end_2d();
    check_against_golden(canvas, "timeline_script_error.png");
  }

  TEST_CASE("the stroke's ball diagram: the tip's dot at the offset, the miscue ring, speed and elevation (README's)") {
    // `stroke 1.5 0.3 -0.25 12`: a fast stroke with a little right english and draw, the butt raised 12
    // degrees, as the timeline picture and the window draw it.
    Stroke stroke;
    stroke.speed = 1.5;
    stroke.side = 0.3;
    stroke.height = -0.25;
    stroke.elevation_deg = 12;
    HeadlessCanvas canvas;
    std::string error;
    REQUIRE_MESSAGE(canvas.open(240, 96, 20, error), error);
    ImDrawList* list = canvas.begin_2d();
    list->AddRectFilled(ImVec2(0, 0), ImVec2(240, 96), IM_COL32(22, 24, 28, 255));
    const ImVec2 size = stroke_diagram_size(canvas.fonts());
    draw_stroke_diagram(*list, stroke, canvas.fonts(),
                        ImVec2(std::round((240 - size.x) / 2), std::round((96 - size.y) / 2)));
    canvas.end_2d();
    check_against_golden(canvas, "stroke.png");
  }

  TEST_CASE("the standard table's numbering from above: rails, pockets and balls (README's picture)") {
    // scenes/numbering.scn as `billiards-preview scenes/numbering.scn --at 0 --overlay table` draws it.
    const ShotResult loaded = load_shot(test::require_file(test::source_path("scenes/numbering.scn")), "numbering", {});
    REQUIRE(loaded.shot);
    const Shot& shot = *loaded.shot;
    HeadlessCanvas canvas;
    const FrameState frame = draw_shot_start(canvas, shot);
    ImDrawList* list = canvas.begin_2d();
    draw_table_numbering(*list, OverlayFrame{shot, 0.0, frame.camera, 960.0, 540.0, canvas.fonts()});
    canvas.end_2d();
    check_against_golden(canvas, "numbering.png");
  }
  TEST_CASE("the aim of a pot cue: ghost ball, aim line and the ball's line to the pocket (README's picture)") {
    // scenes/pot_corner.scn as `billiards-preview scenes/pot_corner.scn --at 0 --overlay aim --size 960x540`
    // draws it: the cue ball's way to where it touches the 3 (as played), the ghost ball there, and the
    // 3's line to the top-right corner.
    const ShotResult loaded =
        load_shot(test::require_file(test::source_path("scenes/pot_corner.scn")), "pot_corner", {});
    REQUIRE(loaded.shot);
    const Shot& shot = *loaded.shot;
    HeadlessCanvas canvas;
    const FrameState frame = draw_shot_start(canvas, shot);
    ImDrawList* list = canvas.begin_2d();
    PreviewOverlays aim;
    aim.aim = true;
    draw_overlays(*list, OverlayFrame{shot, 0.0, frame.camera, 960.0, 540.0, canvas.fonts()}, aim);
    canvas.end_2d();
    check_against_golden(canvas, "aim.png");
  }
}
