#include "viewer_state.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene_file.h"

namespace bsim {

namespace {
constexpr double kDegPerPixel = 0.3;                        // orbit speed of a mouse drag
constexpr double kMinDistance = 0.15, kMaxDistance = 20.0;  // m
}  // namespace

ViewCamera OrbitCamera::view() const {
  const double yaw = radians(yaw_deg), pitch = radians(pitch_deg);
  ViewCamera v;
  v.target = target;
  v.eye = target + distance * Vec3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
  return v;
}

void OrbitCamera::orbit(double dx, double dy) {
  yaw_deg -= dx * kDegPerPixel;
  pitch_deg = std::clamp(pitch_deg + dy * kDegPerPixel, -85.0, 89.0);
}

void OrbitCamera::pan(double dx, double dy, double view_height_px) {
  const CameraView lens = camera_view(view(), kPictureAspect);
  // Move the target so the point under the cursor follows it.
  const double metres_per_px = 2 * distance * lens.half_height() / view_height_px;
  target += (-dx * lens.right() + dy * lens.up()) * metres_per_px;
}

void OrbitCamera::zoom(double steps) {
  distance = std::clamp(distance * std::pow(0.88, steps), kMinDistance, kMaxDistance);
}

double ViewerState::duration() const { return shot ? shot->timeline.duration() : 0; }

void ViewerState::set_time(double t) {
  time = std::clamp(t, 0.0, duration());
  replay = false;
}

MovieFrame ViewerState::shown() const {
  if (!shot || !replay) return {time, false, 1.0};
  return shot->movie.at(movie_time());
}

double ViewerState::movie_duration() const { return shot ? shot->movie.duration() : 0; }

double ViewerState::movie_time() const { return shot ? shot->movie.movie_time(time, replay) : time; }

void ViewerState::set_movie_time(double t) {
  if (!shot) return;
  const MovieFrame frame = shot->movie.at(std::clamp(t, 0.0, movie_duration()));
  time = frame.time;
  replay = frame.replay;
}

void ViewerState::step_frames(int frames) {
  // Land on frame boundaries, as the movie samples them.
  const double frame = std::round(movie_time() * fps) + frames;
  set_movie_time(frame / fps);
  playing = false;
}

void ViewerState::step_event(int direction) {
  if (!shot) return;
  const auto& events = shot->timeline.events();
  constexpr double kSame = 1e-9;  // s; events closer than this count as the one we are on
  if (direction > 0) {
    for (const Event& e : events)
      if (e.time > time + kSame) {
        set_time(e.time);
        break;
      }
  } else {
    for (auto it = events.rbegin(); it != events.rend(); ++it)
      if (it->time < time - kSame) {
        set_time(it->time);
        break;
      }
  }
  playing = false;
}

void ViewerState::step_shot(int direction) {
  if (!shot) return;
  constexpr double kSame = 1e-9;  // s; a strike closer than this is the one we are on
  const std::vector<ShotSpan>& spans = shot->timeline.shots();
  if (direction > 0) {
    for (const ShotSpan& s : spans)
      if (s.cue > time + kSame) {
        set_time(s.cue);
        break;
      }
  } else {
    for (auto it = spans.rbegin(); it != spans.rend(); ++it)
      if (it->cue < time - kSame) {
        set_time(it->cue);
        break;
      }
  }
  playing = false;
}

int ViewerState::shot_in_play() const { return shot ? shot->timeline.shot_at(time) : 0; }

int ViewerState::shot_count() const { return shot ? std::max(shot->timeline.shot_count(), 1) : 1; }

bool load_into(ViewerState& state) {
  LoadedShot loaded = load_source(state.source);
  state.messages = std::move(loaded.messages);
  state.load_failed = !loaded.scripted();
  if (!loaded.scripted()) return false;
  state.shot = std::move(loaded.shot);
  state.timeline = timeline_data(*state.shot);
  state.paths = overlay_paths(*state.shot);
  state.set_time(state.time);  // keep the time, within the new shot
  ++state.reloads;
  return true;
}

bool write_camera_key(ViewerState& state, const CameraPlacement& placement) {
  const auto fail = [&](const std::string& why) {
    state.notice = why;
    state.notice_is_error = true;
    return false;
  };
  if (!state.source.path) return fail("the built-in break has no file to write the camera into; open a scene file");
  if (state.source.strict)
    return fail(
        "with --strict the scene may not use camera keys (an extension): run without --strict to write the camera");
  if (!state.free_camera) return fail("place the camera with the free camera: press C, frame the shot, then the key");
  const std::string& path = *state.source.path;
  std::string error;
  // The file as it is on disk now, not as last loaded: an editor may have saved it since.
  const std::optional<std::string> before = read_scene_file(path, error);
  if (!before) return fail(error);
  const CameraEdit edit = place_camera(*before, state.source.shown_path, state.time, placement);
  if (!edit.error.empty()) return fail(edit.error);
  if (edit.text == *before) {
    state.notice = "line " + std::to_string(edit.line) + " already reads: " + edit.description;
    state.notice_is_error = false;
    return false;
  }
  if (std::string failed = replace_scene_file(path, *before, edit.text); !failed.empty()) return fail(failed);
  state.edits.record(*before, edit.text);
  state.notice = (edit.replaced ? "replaced line " : "wrote line ") + std::to_string(edit.line) + ": " +
                 edit.description + "   (U undoes; the previous file is in " + backup_path(path) + ")";
  state.notice_is_error = false;
  return true;
}

bool undo_camera_key(ViewerState& state) {
  if (!state.source.path) return false;
  const std::string error = state.edits.undo(*state.source.path);
  state.notice = error.empty() ? "undone: " + *state.source.path + " is back as it was" : error;
  state.notice_is_error = !error.empty();
  return error.empty();
}

FileWatch::FileWatch(std::optional<std::string> path) {
  if (path) path_ = *path;
  changed();
}

bool FileWatch::changed() {
  if (!path_) return false;
  std::error_code ec;
  const bool exists = std::filesystem::is_regular_file(*path_, ec);
  const auto stamp = exists ? std::filesystem::last_write_time(*path_, ec) : std::filesystem::file_time_type{};
  const auto size = exists ? std::filesystem::file_size(*path_, ec) : 0;
  const bool different = exists != exists_ || stamp != stamp_ || size != size_;
  exists_ = exists;
  stamp_ = stamp;
  size_ = size;
  return different;
}

}  // namespace bsim
