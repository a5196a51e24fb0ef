#include "camera_edit.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <utility>

#include "atomic_file.h"
#include "ball_track.h"
#include "camera_moment.h"
#include "camera_script.h"
#include "camera_splice.h"
#include "scene_file.h"
#include "shot.h"

namespace bsim {

namespace fs = std::filesystem;

namespace {

int line_at(std::string_view text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

/// The camera the placement asks for, given the description that already starts at the moment.
CameraShot placed_shot(const CameraPlacement& placement, const CameraShot* existing, const Scene& scene,
                       const Timeline& timeline, double t) {
  CameraShot shot;
  if (placement.kind == CameraPlacement::Kind::hover) {
    shot.mode = CameraMode::hover;
    shot.location = to_millimetre(placement.eye);
    shot.target = to_millimetre(placement.look_at);
    return shot;
  }
  shot.ball = placement.ball;
  const bool looking = existing && existing->mode == CameraMode::look && existing->ball == placement.ball;
  if (!looking) {
    shot.mode = CameraMode::look;
    shot.location = to_millimetre(placement.eye);
    return shot;
  }
  // The eye as the follow camera's offset: ahead, left and up in the ball's frame at time t.
  const BallTrack track(timeline, placement.ball, struck_heading(scene, timeline, placement.ball),
                        later_strikes(scene, timeline, placement.ball));
  const Vec3 ahead = track.heading(t), left(-ahead.y(), ahead.x(), 0), from = placement.eye - track.position(t);
  shot.mode = CameraMode::follow;
  shot.location = to_millimetre(Vec3(from.dot(ahead), from.dot(left), from.z()));
  if (shot.location.norm() == 0) shot.location = Vec3(0, 0, 0.001);  // a follow camera never sits on its ball
  return shot;
}

std::string first_error(const std::vector<Diagnostic>& diagnostics, const std::string& shown_path) {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::error) return format_diagnostic(d, shown_path);
  return shown_path + ": error: the scene does not load";
}

std::string system_error(const std::string& what, const std::string& path) {
  return path + ": error: cannot " + what + ": " + std::strerror(errno);
}

}  // namespace

CameraEdit place_camera(std::string_view text, const std::string& shown_path, double t,
                        const CameraPlacement& placement) {
  CameraEdit edit;
  ShotResult loaded = load_shot(text, fs::path(shown_path).stem().string());
  const Shot* shot = loaded.shot.get();
  if (!shot) {
    edit.error = "the camera was not written: the scene file has errors; fix them first (" +
                 first_error(loaded.diagnostics, shown_path) + ")";
    return edit;
  }
  const Scene& scene = shot->scene;
  const Timeline& timeline = shot->timeline;
  if (placement.kind == CameraPlacement::Kind::ball &&
      (placement.ball < 0 || placement.ball >= static_cast<int>(scene.balls.size()))) {
    edit.error = "the camera was not written: the scene file has no ball " + std::to_string(placement.ball);
    return edit;
  }
  t = std::clamp(t, 0.0, timeline.duration());
  const NamedMoment moment = name_moment(timeline, t, kKeySnap);

  // Each description's instant, the one (if any) already at this moment, and the first that starts later.
  std::optional<std::size_t> existing, before;
  for (std::size_t i = 0; i < scene.camera.size(); ++i) {
    const std::optional<KeyInstant> at = resolve_camera_key(scene.camera[i], scene, timeline).instant;
    if (!at) continue;
    if (!existing && at->time == moment.time && at->event == moment.event) existing = i;
    const bool later = at->time > moment.time ||
                       (at->time == moment.time && at->event >= 0 && moment.event >= 0 && at->event > moment.event);
    if (!before && later) before = i;
  }
  CameraShot camera = placed_shot(placement, existing ? &scene.camera[*existing] : nullptr, scene, timeline, t);
  camera.key = moment.key;
  if (moment.key.kind == CameraKeyKind::event) camera.event = moment.event;
  camera.pre = kWrittenPre;
  camera.post = kWrittenPost;
  const CameraSplice splice = existing
                                  ? replace_camera_mode(text, scene, *existing, camera_mode_text(camera))
                                  : insert_camera_description(text, scene, before, camera_description_text(camera));
  if (!splice.error.empty()) {
    edit.error = "the camera was not written: " + splice.error;
    return edit;
  }
  edit.replaced = existing.has_value();
  edit.text = splice.text;
  edit.description = edit.text.substr(splice.begin, splice.end - splice.begin);
  edit.line = line_at(edit.text, splice.begin);
  return edit;
}

std::optional<int> ball_at_pixel(const Timeline& timeline, double t, const ViewCamera& camera, double width,
                                 double height, double x, double y) {
  if (width <= 0 || height <= 0) return std::nullopt;
  // The ray through the pixel, in the frame view_matrix() and projection_matrix() use.
  const Vec3 ray = camera_view(camera, width / height).ray(picture_point(x, y, width, height));
  const double radius = timeline.physics().ball_radius * 1.25;
  std::optional<int> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int ball = 0; ball < timeline.ball_count(); ++ball) {
    const Vec3 centre = timeline.motion_state(ball, t).position;
    if (centre.z() < 0) continue;  // dropped into a pocket, out of sight
    const Vec3 to = centre - camera.eye;
    const double along = to.dot(ray);
    if (along <= 0) continue;
    const double miss2 = to.squaredNorm() - along * along;
    if (miss2 > radius * radius) continue;
    const double hit = along - std::sqrt(radius * radius - miss2);
    if (hit < best_distance) {
      best_distance = hit;
      best = ball;
    }
  }
  return best;
}

std::string backup_path(const std::string& path) { return path + ".bak"; }

std::string replace_scene_file(const std::string& path, const std::string& previous, const std::string& text) {
  std::error_code ec;
  fs::path target = path;
  if (fs::is_symlink(target, ec)) {
    target = fs::canonical(target, ec);
    if (ec) return path + ": error: cannot follow the link: " + ec.message();
  }
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) return system_error("read", path);
  const mode_t mode = st.st_mode & 07777;
  std::string error;
  if (!write_file_atomically(backup_path(target.string()), previous, error, mode)) return error;
  if (!write_file_atomically(target.string(), text, error, mode)) return error;
  return "";
}

void SceneEdits::record(std::string before, std::string after) {
  changes_.push_back({std::move(before), std::move(after)});
}

std::string SceneEdits::undo(const std::string& path) {
  if (changes_.empty()) return "nothing to undo: the window has not changed " + path;
  std::string error;
  const std::optional<std::string> now = read_scene_file(path, error);
  if (!now) return error;
  if (*now != changes_.back().after)
    return "not undone: " + path +
           " has changed since the window wrote it (the version before the window's change is in " + backup_path(path) +
           ")";
  if (std::string failed = replace_scene_file(path, *now, changes_.back().before); !failed.empty()) return failed;
  changes_.pop_back();
  return "";
}

}  // namespace bsim
