// The timeline picture's labels, as drawn for real scenes: the camera descriptions' labels too long
// for their bars stacked in lanes beside their own bars, never over one another and never under
// another shot; every cut label ending in an ellipsis; every shot's stroke diagram in its section; and
// without --size the event list complete. The pieces are recorded as the picture draws them
// (TimelineLayout::drawn).
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <imgui.h>

#include "builtin_scene.h"
#include "files.h"
#include "headless_canvas.h"
#include "labels.h"
#include "shot.h"
#include "support.h"
#include "timeline_picture.h"

using namespace bsim;

namespace {

const std::string kEllipsis = "\xE2\x80\xA6";

bool ends_with_ellipsis(const std::string& text) { return text.ends_with(kEllipsis); }

struct Drawn {
  TimelineData data;
  std::vector<TimelineDrawn> pieces;
  TimelineAxis axis;
};

/// The picture of `data` as billiards-preview draws it: `width` px wide and, with `height` 0, as tall
/// as it needs (no --size) at 16 px text.
Drawn draw(TimelineData data, int width, int height, float text_px) {
  Drawn d{std::move(data), {}, {}};
  HeadlessCanvas canvas;
  std::string error;
  const bool fit_all = height == 0;
  if (fit_all) {
    ImFontAtlas atlas;
    const UiFonts fonts = add_ui_fonts(atlas, text_px);
    atlas.Build();
    height = static_cast<int>(timeline_height(d.data, fonts, static_cast<float>(width))) + 1;
  }
  REQUIRE_MESSAGE(canvas.open(width, height, text_px, error), error);
  ImDrawList* list = canvas.begin_2d();
  TimelineLayout layout{0, 0, float(width), float(height)};
  layout.fit_all = fit_all;
  layout.drawn = &d.pieces;
  d.axis = draw_timeline(*list, d.data, canvas.fonts(), layout);
  canvas.end_2d();
  return d;
}

TimelineData runout(bool automatic) {
  const ShotResult loaded = load_shot(test::require_file(test::source_path("scenes/runout.scn")), "runout", {},
                                      automatic ? CameraChoice::automatic : CameraChoice::scene);
  REQUIRE(loaded.scripted());
  return timeline_data(*loaded.shot);
}

/// The checks every picture of a scene of several shots passes.
void check_labels(const Drawn& d) {
  const float x0 = d.axis.x0, ppm = d.axis.pixels_per_second;
  std::vector<const TimelineDrawn*> lanes;
  std::vector<int> strokes(d.data.shots.size(), 0);
  for (const TimelineDrawn& p : d.pieces) {
    if (p.kind == TimelineDrawn::Kind::lane_label) lanes.push_back(&p);
    if (p.kind == TimelineDrawn::Kind::stroke) {
      REQUIRE(p.shot >= 0);
      const TimelineShotSection& s = d.data.shots[static_cast<std::size_t>(p.shot)];
      ++strokes[static_cast<std::size_t>(p.shot)];
      CHECK(p.x0 >= x0 + s.start * ppm);  // inside its own section
      CHECK(p.x1 <= x0 + s.end * ppm + 1);
    }
    if (p.kind == TimelineDrawn::Kind::shot_text) {
      const TimelineShotSection& s = d.data.shots[static_cast<std::size_t>(p.shot)];
      CAPTURE(p.text);
      CHECK(p.x1 <= x0 + s.end * ppm + 1);
      // Whole, or cut with an ellipsis.
      if (p.text != s.label && p.text != s.detail) {
        std::size_t from = 0;
        for (std::size_t end = p.text.find('\n'); from != std::string::npos;
             from = end == std::string::npos ? end : end + 1, end = p.text.find('\n', from)) {
          const std::string line = p.text.substr(from, end == std::string::npos ? end : end - from);
          CHECK((s.label.starts_with(line) || s.detail.find(line) != std::string::npos || ends_with_ellipsis(line)));
        }
      }
    }
  }
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    CAPTURE(k);
    CHECK(strokes[k] == 1);  // each shot's stroke, whatever its section's width
  }
  REQUIRE_FALSE(lanes.empty());
  for (const TimelineDrawn* l : lanes) {
    CAPTURE(l->text);
    // Starts at its bar, or left of it (the picture's right edge) but never before its shot's start.
    const float bar = x0 + static_cast<float>(l->span->begin) * ppm;
    double shot_start = 0;
    for (const TimelineShotSection& s : d.data.shots)
      if (s.start <= l->span->begin) shot_start = s.start;
    CHECK(l->x0 <= bar + 0.5f);
    CHECK(l->x0 >= x0 + static_cast<float>(shot_start) * ppm - 0.5f);
    CHECK((l->text.find(l->span->label) != std::string::npos || ends_with_ellipsis(l->text)));
    for (const TimelineDrawn* other : lanes) {
      if (other == l) continue;
      const bool apart = l->x1 <= other->x0 || other->x1 <= l->x0 || l->y1 <= other->y0 || other->y1 <= l->y0;
      CHECK_MESSAGE(apart, "\"" << l->text << "\" overlaps \"" << other->text << "\"");
    }
  }
}

int count(const Drawn& d, TimelineDrawn::Kind kind) {
  int n = 0;
  for (const TimelineDrawn& p : d.pieces) n += p.kind == kind;
  return n;
}

}  // namespace

TEST_SUITE("timeline picture layout") {
  TEST_CASE("scenes/runout.scn: labels stacked beside their bars, cut with an ellipsis, every shot's stroke") {
    SUBCASE("the default picture") { check_labels(draw(runout(false), 1600, 0, 16)); }
    SUBCASE("--size 3200x900") { check_labels(draw(runout(false), 3200, 900, 20)); }
    SUBCASE("--camera auto") { check_labels(draw(runout(true), 1600, 0, 16)); }
  }

  TEST_CASE("without --size the list names every event and pocket drop (the built-in break)") {
    const ShotResult loaded = load_shot(builtin_scene_text(), "break");
    REQUIRE(loaded.scripted());
    const Drawn d = draw(timeline_data(*loaded.shot), 1600, 0, 16);
    CHECK(count(d, TimelineDrawn::Kind::list_more) == 0);
    CHECK(count(d, TimelineDrawn::Kind::list_line) == static_cast<int>(d.data.events.size() + d.data.drops.size()));
  }

  TEST_CASE("a picture too short for the list ends it with \"… and N more\", N the ones left out") {
    const ShotResult loaded = load_shot(builtin_scene_text(), "break");
    REQUIRE(loaded.scripted());
    const Drawn d = draw(timeline_data(*loaded.shot), 800, 300, 11);
    const int listed = count(d, TimelineDrawn::Kind::list_line);
    REQUIRE(count(d, TimelineDrawn::Kind::list_more) == 1);
    for (const TimelineDrawn& p : d.pieces)
      if (p.kind == TimelineDrawn::Kind::list_more)
        CHECK(p.text == kEllipsis + " and " +
                            std::to_string(d.data.events.size() + d.data.drops.size() - std::size_t(listed)) + " more");
  }

  TEST_CASE("the legend explains every kind of tick, a pocket's jaw among them, and the list names the jaw") {
    // The 1 rattles in the top-right corner's jaws (pocket 2).
    const ShotResult loaded = load_shot(
        "cue 0 45\n"
        "ball 0 0.5176 -0.1683 0.028575 1.7678 1.7678 0 1 0 0 0\n"
        "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n",
        "rattle");
    REQUIRE(loaded.scripted());
    const Drawn d = draw(timeline_data(*loaded.shot), 1600, 0, 16);
    std::vector<std::string> legend;
    for (const TimelineDrawn& p : d.pieces)
      if (p.kind == TimelineDrawn::Kind::legend_key) legend.push_back(p.text);
    const std::vector<std::string> expected = {"start / end", "cue", "ball-ball", "ball-rail", "ball-jaw"};
    REQUIRE(legend.size() >= expected.size() + 1);
    for (std::size_t k = 0; k < expected.size(); ++k) CHECK(legend[k] == expected[k]);
    CHECK(legend.back() == "interpolation window (\xE2\x96\xB2 its event)");  // every key fits at 1600 px
    int jaw_lines = 0;
    for (const TimelineDrawn& p : d.pieces)
      if (p.kind == TimelineDrawn::Kind::list_line &&
          p.text.find("ball 1 \xE2\x80\x93 jaw of pocket 2") != std::string::npos)
        ++jaw_lines;
    CHECK(jaw_lines == 5);
    // Its own colour, told apart from every other tick's.
    for (EventType other : {EventType::start, EventType::cue, EventType::ball_ball, EventType::ball_rail})
      CHECK(event_color(EventType::ball_jaw) != event_color(other));
  }
}
