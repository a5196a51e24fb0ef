#include "camera_edit.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>
#include <utility>

#include "atomic_file.h"
#include "ball_track.h"
#include "camera_key.h"
#include "camera_script.h"
#include "camera_splice.h"
#include "scene_file.h"
#include "shot.h"

namespace bsim {

namespace fs = std::filesystem;

namespace {

/// A number to the millimetre (or millisecond), without trailing zeros: "1.25", "-0.4", "2".
std::string fixed3(double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.3f", value);
  std::string text = buffer;
  while (!text.empty() && text.back() == '0') text.pop_back();
  if (!text.empty() && text.back() == '.') text.pop_back();
  if (text == "-0") text = "0";
  return text;
}

/// The ordinal of the k-th (1-based) of n contacts: k up to the fifth, CameraKey::kLast for the last
/// of more than five; nothing when it has no name.
std::optional<int> key_ordinal(std::size_t k, std::size_t n) {
  if (k >= 1 && k <= 5) return static_cast<int>(k);
  if (k == n) return CameraKey::kLast;
  return std::nullopt;
}

CameraKey key_of(CameraKeyKind kind, int a = -1, int b = -1, int ordinal = 1) {
  CameraKey key;
  key.kind = kind;
  key.a = a;
  key.b = b;
  key.ordinal = ordinal;
  return key;
}

struct Instant {
  double time = 0;
  int event = -1;
};

/// The text of a key that counts within shot `shot` (0-based) when the scene has several, else over it.
std::string shot_key_text(const Timeline& timeline, int shot, CameraKeyKind kind, int a = -1, int b = -1,
                          int ordinal = 1) {
  CameraKey key = key_of(kind, a, b, ordinal);
  key.shot = timeline.shot_count() > 1 ? shot : -1;
  return camera_key_text(key);
}

/// Every moment a key can name, in the order the events list them (then the later shots' starts). In a
/// scene of several shots each key counts within its shot (`shot 2 cue`, `shot 2 hit 0 3`), so it stays
/// on its moment whatever the shots before it do.
std::vector<NamedMoment> nameable_moments(const Timeline& timeline) {
  std::vector<NamedMoment> moments;
  std::map<std::tuple<int, int, int>, std::vector<Instant>> hits;  // by shot and the two balls
  std::map<std::pair<int, int>, std::vector<Instant>> cushions;    // by shot and ball
  std::map<std::pair<int, int>, std::vector<Instant>> jaws;        // by shot and ball
  std::vector<int> cues_named;
  const int last = std::max(1, timeline.shot_count()) - 1;
  for (const Event& e : timeline.events()) {
    switch (e.type) {
      case EventType::start:
        moments.push_back({shot_key_text(timeline, 0, CameraKeyKind::start), e.time, e.index});
        break;
      case EventType::end:
        moments.push_back({shot_key_text(timeline, last, CameraKeyKind::end), e.time, e.index});
        break;
      case EventType::cue:
        if (std::find(cues_named.begin(), cues_named.end(), e.shot) == cues_named.end())
          moments.push_back({shot_key_text(timeline, e.shot, CameraKeyKind::cue), e.time, e.index});
        cues_named.push_back(e.shot);
        break;
      case EventType::ball_ball:
        for (const Contact& c : e.contacts)
          hits[{e.shot, std::min(c.a, c.b), std::max(c.a, c.b)}].push_back({c.time, e.index});
        break;
      case EventType::ball_rail:
        if (!e.balls.empty()) cushions[{e.shot, e.balls[0]}].push_back({e.time, e.index});
        break;
      case EventType::ball_jaw:
        if (!e.balls.empty()) jaws[{e.shot, e.balls[0]}].push_back({e.time, e.index});
        break;
    }
  }
  for (int k = 1; k <= last; ++k)
    moments.push_back(
        {shot_key_text(timeline, k, CameraKeyKind::start), timeline.shots()[static_cast<std::size_t>(k)].start, -1});
  // Counted in time order, as the keys resolve (camera_key.cpp).
  for (auto& [balls, found] : hits) {
    std::stable_sort(found.begin(), found.end(), [](const Instant& x, const Instant& y) { return x.time < y.time; });
    const auto [shot, a, b] = balls;
    for (std::size_t k = 0; k < found.size(); ++k)
      if (const auto ordinal = key_ordinal(k + 1, found.size()))
        moments.push_back(
            {shot_key_text(timeline, shot, CameraKeyKind::hit, a, b, *ordinal), found[k].time, found[k].event});
  }
  for (const auto& [kind, contacts] :
       {std::pair{CameraKeyKind::cushion, &cushions}, std::pair{CameraKeyKind::jaw, &jaws}})
    for (const auto& [ball, found] : *contacts)
      for (std::size_t k = 0; k < found.size(); ++k)
        if (const auto ordinal = key_ordinal(k + 1, found.size()))
          moments.push_back(
              {shot_key_text(timeline, ball.first, kind, ball.second, -1, *ordinal), found[k].time, found[k].event});
  std::vector<std::pair<int, int>> dropped;  // shot and ball: a key names a ball's first drop in a shot
  for (const PocketDrop& d : timeline.pocket_drops()) {
    const std::pair<int, int> which{timeline.shot_count() > 1 ? timeline.shot_at(d.time) : 0, d.ball};
    if (std::find(dropped.begin(), dropped.end(), which) != dropped.end()) continue;
    dropped.push_back(which);
    moments.push_back({shot_key_text(timeline, which.first, CameraKeyKind::drop, d.ball), d.time, -1});
  }
  return moments;
}

Vec3 rounded(const Vec3& v) {
  const auto mm = [](double x) { return std::strtod(fixed3(x).c_str(), nullptr); };
  return {mm(v.x()), mm(v.y()), mm(v.z())};
}

int line_at(std::string_view text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

/// The camera the placement asks for, given the description that already starts at the moment.
CameraShot placed_shot(const CameraPlacement& placement, const CameraShot* existing, const Scene& scene,
                       const Timeline& timeline, double t) {
  CameraShot shot;
  if (placement.kind == CameraPlacement::Kind::hover) {
    shot.mode = CameraMode::hover;
    shot.location = rounded(placement.eye);
    shot.target = rounded(placement.look_at);
    return shot;
  }
  shot.ball = placement.ball;
  const bool looking = existing && existing->mode == CameraMode::look && existing->ball == placement.ball;
  if (!looking) {
    shot.mode = CameraMode::look;
    shot.location = rounded(placement.eye);
    return shot;
  }
  // The eye as the follow camera's offset: ahead, left and up in the ball's frame at time t.
  const BallTrack track(timeline, placement.ball, struck_heading(scene, timeline, placement.ball),
                        later_strikes(scene, timeline, placement.ball));
  const Vec3 ahead = track.heading(t), left(-ahead.y(), ahead.x(), 0), from = placement.eye - track.position(t);
  shot.mode = CameraMode::follow;
  shot.location = rounded(Vec3(from.dot(ahead), from.dot(left), from.z()));
  if (shot.location.norm() == 0) shot.location = Vec3(0, 0, 0.001);  // a follow camera never sits on its ball
  return shot;
}

/// The part of a description after its windows: "hover 1 2 3 0 0 0", "look 1 2 3 5", "follow 5 -1 0 0.5".
std::string mode_text(const CameraShot& c) {
  const auto vec = [](const Vec3& v) { return fixed3(v.x()) + " " + fixed3(v.y()) + " " + fixed3(v.z()); };
  switch (c.mode) {
    case CameraMode::hover: return "hover " + vec(c.location) + " " + vec(c.target);
    case CameraMode::look: return "look " + vec(c.location) + " " + std::to_string(c.ball);
    case CameraMode::follow: return "follow " + std::to_string(c.ball) + " " + vec(c.location);
  }
  return "";
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

NamedMoment name_moment(const Timeline& timeline, double t) {
  const std::vector<NamedMoment> moments = nameable_moments(timeline);
  const NamedMoment* nearest = nullptr;
  for (const NamedMoment& m : moments)
    if (!nearest || std::abs(m.time - t) < std::abs(nearest->time - t)) nearest = &m;
  if (nearest && std::abs(nearest->time - t) <= kKeySnap) return *nearest;
  // `at T` counts from the start of the shot (in a scene of several, of the shot in play: `shot K at
  // T`); T rounded down to the millisecond stays in the shot.
  const bool several = timeline.shot_count() > 1;
  const int shot = several ? timeline.shot_at(t) : -1;
  const double start = several                     ? timeline.shots()[static_cast<std::size_t>(shot)].start
                       : timeline.events().empty() ? 0.0
                                                   : timeline.events().front().time;
  CameraKey key = key_of(CameraKeyKind::at);
  key.shot = shot;
  key.seconds = std::strtod(fixed3(std::max(0.0, std::floor((t - start) * 1000 + 1e-6) / 1000)).c_str(), nullptr);
  return {camera_key_text(key), start + key.seconds, -1};
}

std::string format_description(const std::string& key, double pre, double post, const CameraShot& camera) {
  return "event " + key + " " + fixed3(pre) + " " + fixed3(post) + " " + mode_text(camera);
}

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
  const NamedMoment moment = name_moment(timeline, t);

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
  const CameraShot camera = placed_shot(placement, existing ? &scene.camera[*existing] : nullptr, scene, timeline, t);
  const CameraSplice splice =
      existing ? replace_camera_mode(text, scene, *existing, mode_text(camera))
               : insert_camera_description(text, scene, before,
                                           format_description(moment.key, kWrittenPre, kWrittenPost, camera));
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
