// --at: one frame of the shot, drawn headless, with optional overlays.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <imgui.h>

#include "commands.h"
#include "headless_canvas.h"
#include "overlays.h"
#include "scene_renderer.h"
#include "timeline_picture.h"

namespace bsim {

namespace {
/// Snapshots are single frames, so they can afford antialiasing.
constexpr int kSnapshotSamples = 4;
/// Without --size the timeline is wider than a frame (a long shot's events need the room) and as tall
/// as it needs to be, within these bounds.
constexpr int kTimelineWidth = 1600, kTimelineMinHeight = 360, kTimelineMaxHeight = 8000;
}  // namespace

std::optional<double> resolve_time(const TimeSpec& at, const Timeline& timeline, std::string& error) {
  if (at.shot >= 1) {
    const int shots = timeline.shot_count();
    if (at.shot > shots) {
      error = "--at shot:" + std::to_string(at.shot) + ": this scene has " + std::to_string(shots) +
              (shots == 1 ? " shot, numbered 1" : " shots, numbered 1 to " + std::to_string(shots)) +
              " (one per cue line)";
      return std::nullopt;
    }
    return timeline.shots()[static_cast<std::size_t>(at.shot - 1)].cue;
  }
  if (at.event < 0) return std::clamp(at.seconds, 0.0, timeline.duration());
  const auto count = static_cast<int>(timeline.events().size());
  if (at.event >= count) {
    error = "--at event:" + std::to_string(at.event) + ": this shot has " + std::to_string(count) +
            " events, numbered 0 to " + std::to_string(count - 1) + " (see --timeline)";
    return std::nullopt;
  }
  return timeline.events()[static_cast<std::size_t>(at.event)].time;
}

/// Makes the folder `file` goes into, if it has one and it is missing.
static bool make_parent_directory(const std::string& file, std::string& error) {
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  std::error_code ec;
  if (parent.empty() || std::filesystem::is_directory(parent, ec)) return true;
  std::filesystem::create_directories(parent, ec);
  if (ec) error = "cannot create the directory " + parent.string() + ": " + ec.message();
  return !ec;
}

float picture_text_px(int height) { return std::clamp(static_cast<float>(height) / 720.f * 17.f, 11.f, 34.f); }

int run_snapshot(const PreviewOptions& options, const Shot& shot) {
  std::string error;
  std::vector<double> times;
  for (const TimeSpec& at : options.at) {
    const std::optional<double> t = resolve_time(at, shot.timeline, error);
    if (!t) {
      std::cerr << "billiards-preview: " << error << "\n";
      return 2;
    }
    if (at.event < 0 && at.shot < 1 && at.seconds > shot.timeline.duration())
      std::cerr << "billiards-preview: warning: --at " << at.seconds << " is after the end of the shot; showing "
                << shot.timeline.duration() << " s\n";
    times.push_back(*t);
  }
  // The folder each picture goes into is made if missing, for a directory (-o shots/), a pattern
  // (-o takes/shot_%t.png) and a file name (-o takes/shot.png) alike.
  for (const std::string& picture : options.pictures)
    if (!make_parent_directory(picture, error)) {
      std::cerr << "billiards-preview: error: " << error << "\n";
      return 1;
    }
  HeadlessCanvas canvas;
  SceneRenderer renderer;
  if (!canvas.open(options.width, options.height, picture_text_px(options.height), error) || !renderer.init(error)) {
    std::cerr << "billiards-preview: error: " << error << "\n";
    return 1;
  }
  renderer.set_multisampling(kSnapshotSamples);
  renderer.set_scene(shot.scene);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    const FrameState frame = scripted_frame(shot, t);
    renderer.draw(shot.scene, frame, options.width, options.height);
    ImDrawList* list = canvas.begin_2d();
    draw_overlays(*list,
                  OverlayFrame{shot, t, frame.camera, double(options.width), double(options.height), canvas.fonts()},
                  options.overlays);
    canvas.end_2d();
    if (!canvas.write_png(options.pictures[i], error)) {
      std::cerr << "billiards-preview: error: " << error << "\n";
      return 1;
    }
    if (!options.quiet) std::cerr << "wrote " << options.pictures[i] << "\n";
  }
  return 0;
}

int run_timeline_picture(const PreviewOptions& options, const TimelineData& data) {
  // Without --size, exactly as tall as the picture needs to show everything: every label and the
  // whole event list (measured with the fonts it will be drawn in).
  const int width = options.size_given ? options.width : kTimelineWidth;
  const float text_px = options.size_given ? std::clamp(std::min(options.height / 36.f, width / 90.f), 11.f, 20.f) : 16.f;
  int height = options.size_given ? options.height : kTimelineMinHeight;
  if (!options.size_given) {
    ImFontAtlas atlas;
    const UiFonts fonts = add_ui_fonts(atlas, text_px);
    atlas.Build();
    const float needed = std::ceil(timeline_height(data, fonts, static_cast<float>(width))) + 1;
    height = std::clamp(static_cast<int>(needed), kTimelineMinHeight, kTimelineMaxHeight);
  }
  std::string error;
  HeadlessCanvas canvas;
  if (!canvas.open(width, height, text_px, error)) {
    std::cerr << "billiards-preview: error: " << error << "\n";
    return 1;
  }
  ImDrawList* list = canvas.begin_2d();
  TimelineLayout layout{0, 0, float(width), float(height)};
  layout.fit_all = !options.size_given;
  draw_timeline(*list, data, canvas.fonts(), layout);
  canvas.end_2d();
  if (!make_parent_directory(*options.output, error) || !canvas.write_png(*options.output, error)) {
    std::cerr << "billiards-preview: error: " << error << "\n";
    return 1;
  }
  if (!options.quiet) std::cerr << "wrote " << *options.output << "\n";
  return 0;
}

}  // namespace bsim
