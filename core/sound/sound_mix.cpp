#include "sound_mix.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "camera_interpolation.h"
#include "simulate.h"

namespace bsim {

namespace {

/// How far from the centre a sound at the picture's edge is panned: not all the way, as a
/// listener between two speakers hears a hard-panned click as coming from outside the picture.
constexpr double kPanWidth = 0.8;

std::uint64_t cue_seed(SoundKind kind, int index, int ball) {
  return (static_cast<std::uint64_t>(kind) + 1) * 0x9e3779b97f4a7c15ULL ^
         (static_cast<std::uint64_t>(index) + 1) * 0xc2b2ae3d27d4eb4fULL ^
         (static_cast<std::uint64_t>(ball) + 7) * 0x165667b19e3779f9ULL;
}

/// When a dropped ball comes to rest at the bottom of its pocket: the knock heard.
double landing_time(const Timeline& timeline, const PocketDrop& drop) {
  for (const MotionSegment& segment : timeline.segments(drop.ball))
    if (segment.t0 >= drop.time && segment.start.motion == Motion::pocketed) return segment.t0;
  return drop.time;
}

double pan_of(const SoundSource& shot, double t, const Vec3& where) {
  return kPanWidth * view_position(shot.camera.pose(t), where, kCameraFovDeg);
}

}  // namespace

double view_position(const CameraPose& camera, const Vec3& point, double fov_deg) {
  // The picture's frame as the front ends draw it (a camera on its look point looks straight down).
  const Vec3 f = view_direction(camera.location, camera.look_at);
  const Vec3 right = f.cross(picture_up(f)).normalized();  // forward x up points to the picture's right
  const Vec3 d = point - camera.location;
  const double across = d.dot(right), ahead = d.dot(f);
  const double half = fov_deg * std::numbers::pi / 360.0;
  const double angle = std::atan2(across, std::max(ahead, 0.0));
  return std::clamp(angle / half, -1.0, 1.0);
}

std::vector<SoundCue> sound_cues(const SoundSource& shot) {
  std::vector<SoundCue> cues;
  for (const Event& e : shot.timeline.events()) {
    SoundKind kind;
    switch (e.type) {
      case EventType::cue: kind = SoundKind::cue; break;
      case EventType::ball_ball: kind = SoundKind::ball_ball; break;
      case EventType::ball_rail: kind = SoundKind::ball_rail; break;
      default: continue;
    }
    const int ball = e.balls.empty() ? 0 : e.balls.front();
    if (!e.contacts.empty()) {
      // A group collision clicks once for each of its contacts, at its own time and speed (those gentler
      // than a numbered event are not heard).
      for (const Contact& c : e.contacts)
        if (c.speed >= kMinEventSpeed)
          cues.push_back(
              {kind, c.time, c.speed, pan_of(shot, c.time, c.where), cue_seed(kind, e.index, c.a * 16 + c.b)});
      continue;
    }
    cues.push_back({kind, e.time, e.speed, pan_of(shot, e.time, e.where), cue_seed(kind, e.index, ball)});
  }
  const auto& drops = shot.timeline.pocket_drops();
  for (std::size_t i = 0; i < drops.size(); ++i) {
    const PocketDrop& drop = drops[i];
    const double t = landing_time(shot.timeline, drop);
    const double speed = shot.timeline.state(drop.ball, drop.time).velocity.norm();
    const Vec3 where = shot.scene.pockets[static_cast<std::size_t>(drop.pocket)].center;
    cues.push_back({SoundKind::pocket, t, speed, pan_of(shot, t, where),
                    cue_seed(SoundKind::pocket, static_cast<int>(i), drop.ball)});
  }
  std::stable_sort(cues.begin(), cues.end(), [](const SoundCue& a, const SoundCue& b) { return a.time < b.time; });
  return cues;
}

void mix_cues(const std::vector<SoundCue>& cues, const PhysicsParams& physics, double lead, AudioBuffer& out) {
  const auto length = static_cast<long long>(out.left.size());
  for (const SoundCue& cue : cues) {
    const std::vector<float> sound = synth_impact(cue.kind, cue.speed, cue.seed, physics, out.sample_rate);
    // Equal-power pan: the sum of the channels' powers is the same wherever the sound sits.
    const double angle = (std::clamp(cue.pan, -1.0, 1.0) + 1.0) * std::numbers::pi / 4.0;
    const auto gain_left = static_cast<float>(std::cos(angle)), gain_right = static_cast<float>(std::sin(angle));
    const long long start = std::llround((cue.time - lead) * out.sample_rate);
    for (long long i = std::max(0LL, -start); i < static_cast<long long>(sound.size()); ++i) {
      const long long at = start + i;
      if (at >= length) break;
      out.left[static_cast<std::size_t>(at)] += gain_left * sound[static_cast<std::size_t>(i)];
      out.right[static_cast<std::size_t>(at)] += gain_right * sound[static_cast<std::size_t>(i)];
    }
  }
}

}  // namespace bsim
