#include "camera_script.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "camera_interpolation.h"
#include "camera_moment.h"
#include "table.h"

namespace bsim {

namespace {

/// deg above the horizon of the default camera: high enough to see the whole bed, low enough for depth.
constexpr double kDefaultElevationDeg = 55.0;
/// m the default camera keeps under the room's ceiling.
constexpr double kDefaultCeilingRoom = 0.35;

std::string describe_event(int written, int resolved) {
  if (written == CameraShot::kLastEvent) return "event 65535 (the last event, " + std::to_string(resolved) + ")";
  return "event " + std::to_string(written);
}

/// "hit 0 5 on line 12 (at 3.42 s)".
std::string describe_placed(const CameraShot& shot, double time) {
  char at[48];
  std::snprintf(at, sizeof at, " (at %.3f s)", time);
  return describe_camera_key(shot) + " on line " + std::to_string(shot.loc.line) + at;
}

/// Resolves every listed event number or key to its instant in the shot, or reports why it cannot
/// (an event the shot does not have, a key it never reaches, descriptions out of order).
std::vector<std::optional<KeyInstant>> resolve_events(const Scene& scene, const std::vector<CameraShot>& shots,
                                                      const Timeline& timeline, std::vector<Diagnostic>& diagnostics) {
  std::vector<std::optional<KeyInstant>> resolved;
  std::optional<KeyInstant> latest;
  const CameraShot* latest_shot = nullptr;
  for (const CameraShot& shot : shots) {
    const KeyResolution r = resolve_camera_key(shot, scene, timeline);
    if (!r.instant) {
      diagnostics.push_back({Severity::error, r.where, r.problem});
      resolved.push_back(std::nullopt);
      continue;
    }
    const KeyInstant now = *r.instant;
    // A later instant, or the same one at a later numbered event (simultaneous events keep their order).
    const bool after = !latest || now.time > latest->time ||
                       (now.time == latest->time && now.event >= 0 && latest->event >= 0 && now.event > latest->event);
    if (!after) {
      const bool numbers = shot.key.kind == CameraKeyKind::event && latest_shot->key.kind == CameraKeyKind::event;
      diagnostics.push_back({Severity::error, message_loc(shot.event_loc, shot.loc),
                             numbers ? describe_event(shot.event, now.event) + " is listed after " +
                                           describe_event(latest_shot->event, latest->event) +
                                           ": list the camera's events in increasing order"
                                     : describe_placed(shot, now.time) + " is listed after " +
                                           describe_placed(*latest_shot, latest->time) +
                                           ": list the camera's descriptions in the order they happen"});
      if (now.time == latest->time && now.event == latest->event) latest_shot = &shot;  // the later one names it
    } else {
      latest = now;
      latest_shot = &shot;
    }
    resolved.push_back(now);
  }
  return resolved;
}

bool check_balls(const Scene& scene, const std::vector<CameraShot>& shots, std::vector<Diagnostic>& diagnostics) {
  const int count = static_cast<int>(scene.balls.size());
  bool ok = true;
  for (const CameraShot& shot : shots) {
    if (shot.mode == CameraMode::hover || (shot.ball >= 0 && shot.ball < count)) continue;
    diagnostics.push_back(
        {Severity::error, message_loc(shot.ball_loc, shot.loc),
         "ball " + std::to_string(shot.ball) + " does not exist: the scene has " + counted(count, "ball")});
    ok = false;
  }
  return ok;
}

}  // namespace

std::optional<double> struck_heading(const Scene& scene, const Timeline& timeline, int ball) {
  for (const Event& e : timeline.events()) {
    if (e.type == EventType::start || e.type == EventType::end) continue;
    if (std::find(e.balls.begin(), e.balls.end(), ball) == e.balls.end()) continue;
    if (e.type != EventType::cue) return std::nullopt;
    const auto k = static_cast<std::size_t>(std::clamp(e.shot, 0, scene.shot_count() - 1));
    return scene.cues[k].heading_deg * kDegToRad;
  }
  if (ball == scene.cue().target) return scene.cue().heading_deg * kDegToRad;
  return std::nullopt;
}

std::vector<TrackStrike> later_strikes(const Scene& scene, const Timeline& timeline, int ball) {
  std::vector<TrackStrike> out;
  bool first = true;
  for (const Event& e : timeline.events()) {
    if (e.type == EventType::start || e.type == EventType::end) continue;
    if (std::find(e.balls.begin(), e.balls.end(), ball) == e.balls.end()) continue;
    const bool struck = !first && e.type == EventType::cue && e.shot < timeline.shot_count();
    first = false;
    if (!struck) continue;
    const auto k = static_cast<std::size_t>(std::clamp(e.shot, 0, scene.shot_count() - 1));
    out.push_back(
        {timeline.shots()[static_cast<std::size_t>(e.shot)].start, e.time, scene.cues[k].heading_deg * kDegToRad});
  }
  return out;
}

CameraShot CameraScript::default_shot(const Scene& scene) {
  // The nose lines' extent (the standard bed's when the scene has none).
  const TableRect noses = table_layout(scene).noses;
  const Vec3 low(noses.x0, noses.y0, 0), high(noses.x1, noses.y1, 0);
  const Vec3 centre(0.5 * (low.x() + high.x()), 0.5 * (low.y() + high.y()), 0);
  const double half_x = 0.5 * (high.x() - low.x()), half_y = 0.5 * (high.y() - low.y());
  // Far enough that the long side fills the width with a margin, from the near long side.
  const double distance = 1.15 * half_x / std::tan(0.5 * kCameraFovDeg * kDegToRad) + half_y;
  // Under the room's ceiling (a camera above it sees only the ceiling's back: a black picture): the
  // elevation comes down, the distance kept, until it is kDefaultCeilingRoom under it.
  const double highest =
      std::min(distance * std::sin(kDefaultElevationDeg * kDegToRad), kRoom.ceiling - kDefaultCeilingRoom);
  const double elevation = std::asin(std::clamp(highest / distance, 0.0, 1.0));
  CameraShot shot;
  shot.event = 0;
  shot.mode = CameraMode::hover;
  shot.target = centre;
  shot.location = centre + distance * Vec3(0, -std::cos(elevation), std::sin(elevation));
  return shot;
}

std::optional<CameraScript> CameraScript::build(const Scene& scene, const Timeline& timeline,
                                                std::vector<Diagnostic>& diagnostics) {
  return build(scene, scene.camera, timeline, diagnostics);
}

std::optional<CameraScript> CameraScript::build(const Scene& scene, const std::vector<CameraShot>& shots,
                                                const Timeline& timeline, std::vector<Diagnostic>& diagnostics) {
  const std::size_t errors_before = diagnostics.size();
  const std::vector<std::optional<KeyInstant>> resolved = resolve_events(scene, shots, timeline, diagnostics);
  const bool events_ok = diagnostics.size() == errors_before;
  const bool balls_ok = check_balls(scene, shots, diagnostics);
  if (!balls_ok || !events_ok) return std::nullopt;

  CameraScript script;
  script.timeline_ = &timeline;
  script.shots_ = shots;
  std::vector<double> times;
  for (const std::optional<KeyInstant>& instant : resolved) times.push_back(instant->time);
  if (script.shots_.empty()) {
    script.shots_.push_back(default_shot(scene));
    times.push_back(0.0);
  }
  const double duration = timeline.duration();
  const int count = static_cast<int>(script.shots_.size());

  for (int j = 0; j < count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const double next = j + 1 < count ? times[k + 1] : duration;
    script.segments_.push_back({j, j == 0 ? 0.0 : times[k], next});
    if (j == 0) continue;  // nothing comes before the first description, so nothing to blend from
    const double previous = times[k - 1];
    const CameraShot& shot = script.shots_[k];
    CameraWindow window{j, times[k] - shot.pre * (times[k] - previous), times[k],
                        times[k] + shot.post * (next - times[k])};
    // Windows that would overlap share the span between their events in the ratio of their fractions.
    if (!script.windows_.empty() && script.windows_.back().end > window.begin) {
      CameraWindow& before = script.windows_.back();
      const double ahead = script.shots_[k - 1].post;
      const double meet = previous + (times[k] - previous) * ahead / (ahead + shot.pre);
      before.end = meet;
      window.begin = meet;
    }
    script.windows_.push_back(window);
  }

  script.tracks_.resize(scene.balls.size());
  for (const CameraShot& shot : script.shots_) {
    if (shot.mode == CameraMode::hover) continue;
    auto& track = script.tracks_[static_cast<std::size_t>(shot.ball)];
    if (track) continue;
    track.emplace(timeline, shot.ball, struck_heading(scene, timeline, shot.ball),
                  later_strikes(scene, timeline, shot.ball));
  }
  return script;
}

CameraPose CameraScript::shot_pose(int shot_index, double t) const {
  const CameraShot& shot = shots_[static_cast<std::size_t>(shot_index)];
  CameraPose pose;
  switch (shot.mode) {
    case CameraMode::hover:
      pose.location = shot.location;
      pose.look_at = shot.target;
      break;
    case CameraMode::look:
      pose.location = shot.location;
      pose.look_at = tracks_[static_cast<std::size_t>(shot.ball)]->position(t);
      break;
    case CameraMode::follow: {
      const BallTrack& track = *tracks_[static_cast<std::size_t>(shot.ball)];
      const Vec3 ball = track.position(t);
      const Vec3 ahead = track.heading(t);
      const Vec3 left(-ahead.y(), ahead.x(), 0);
      pose.location = ball + shot.location.x() * ahead + shot.location.y() * left + shot.location.z() * Vec3::UnitZ();
      pose.look_at = ball;
      break;
    }
  }
  return pose;
}

CameraPose CameraScript::interpolate(const CameraWindow& window, double t) const {
  // The seed's second camera interpolation: Bezier look point, slerped direction, Smooth distance.
  const CameraPose from = shot_pose(window.shot - 1, window.begin);
  const CameraPose to = shot_pose(window.shot, window.end);
  const Vec3 middle = shot_pose(window.shot, window.event_time).look_at;
  const double from_distance = (from.look_at - from.location).norm();
  const double to_distance = (to.look_at - to.location).norm();
  // A camera sitting on its look point has no direction; borrow the other end's (or look straight down).
  const Vec3 to_direction = unit_or(to.location, to.look_at, view_direction(from.location, from.look_at));
  const Vec3 from_direction = unit_or(from.location, from.look_at, to_direction);

  const double u = std::clamp((t - window.begin) / (window.end - window.begin), 0.0, 1.0);
  CameraPose pose;
  pose.look_at = bezier(from.look_at, middle, to.look_at, u);
  const Vec3 direction = slerp_unit(from_direction, to_direction, u);
  const double distance = from_distance + (to_distance - from_distance) * smooth(u);
  pose.location = pose.look_at - distance * direction;
  pose.interpolating = true;
  return pose;
}

CameraPose CameraScript::pose(double t) const {
  for (const CameraWindow& window : windows_) {
    if (window.end > window.begin && t >= window.begin && t <= window.end) return interpolate(window, t);
  }
  int shot = segments_.front().shot;
  for (const CameraSegment& segment : segments_) {
    if (t >= segment.begin) shot = segment.shot;
  }
  return shot_pose(shot, t);
}

int CameraScript::shot_at(double t) const {
  if (segments_.empty()) return -1;
  int shot = segments_.front().shot;
  for (const CameraSegment& segment : segments_)
    if (t >= segment.begin) shot = segment.shot;
  return shot;
}

}  // namespace bsim
