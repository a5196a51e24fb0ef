#include "sound_mix.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "camera_view.h"
#include "pocket_fall.h"
#include "simulate.h"

namespace bsim {

namespace {

/// How far from the centre a sound at the picture's edge is panned: not all the way, as a
/// listener between two speakers hears a hard-panned click as coming from outside the picture.
constexpr double kPanWidth = 0.8;

/// m/s: the speed of sound in air at 20 degrees C.
constexpr double kSpeedOfSound = 343.0;

std::uint64_t cue_seed(SoundKind kind, int index, int ball) {
  return (static_cast<std::uint64_t>(kind) + 1) * 0x9e3779b97f4a7c15ULL ^
         (static_cast<std::uint64_t>(index) + 1) * 0xc2b2ae3d27d4eb4fULL ^
         (static_cast<std::uint64_t>(ball) + 7) * 0x165667b19e3779f9ULL;
}

SoundCue event_cue(const SoundSource& shot, SoundKind kind, double t, double speed, const Vec3& where,
                   std::uint64_t seed) {
  const CameraPose pose = shot.camera.pose(t);
  return {kind,  t,
          speed, kPanWidth * view_position(pose, where, kCameraFovDeg),
          seed,  distance_gain((where - pose.location).norm())};
}

/// A collision clicks once for each of its contacts, at its own time and speed (those of a group
/// gentler than a numbered event are not heard). Each click is seeded by its two balls. A group's
/// clicks reach the camera one after another: each is heard its extra way to the camera after the
/// nearest contact's, at the speed of sound. A rack spreads its contacts over about 0.3 m, up to a
/// millisecond of travel, longer than a click's 0.3-0.5 ms contact, so, as a microphone in the room
/// hears them, the break's clicks do not stack into one peak: its loudest instant is 7 dB lower
/// than with every click at its contact's own time. The shot's sounds as a whole keep no travel
/// time (a film keeps its sound on the picture's frame), so a pair's click stays on its event.
void add_contact_clicks(const SoundSource& shot, const Event& e, std::vector<SoundCue>& cues) {
  const Vec3 ear = shot.camera.pose(e.time).location;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Contact& c : e.contacts) nearest = std::min(nearest, (c.where - ear).norm());
  for (const Contact& c : e.contacts) {
    if (c.speed < kMinEventSpeed) continue;
    const double travel = ((c.where - ear).norm() - nearest) / kSpeedOfSound;
    cues.push_back(event_cue(shot, SoundKind::ball_ball, c.time + travel, c.speed, c.where,
                             cue_seed(SoundKind::ball_ball, e.index, c.a * 16 + c.b)));
  }
}

/// A ball's rattle in a pocket's jaws so far: its last knock, and how loud that was heard.
struct Rattle {
  int pocket = -1;
  double time = 0;  ///< s, its last knock
  double peak = 0;  ///< that knock's peak, before placing
};

/// A knock on a pocket's jaw for each ball-jaw event, its modes the pocket's (jaw_seed). A ball's knocks
/// on one pocket's jaws each within kRattleGap of the one before, with no other contact of the ball
/// between them, make one rattle: each later knock peaks at most kRattleFollow of the one before
/// (softer still when it is slower), so the rattle dies away.
void add_jaw_knocks(const SoundSource& shot, std::vector<SoundCue>& cues) {
  std::vector<Rattle> rattles(static_cast<std::size_t>(shot.timeline.ball_count()));
  for (const Event& e : shot.timeline.events()) {
    if (e.type != EventType::ball_jaw) {  // any other contact ends the ball's rattle
      for (int ball : e.balls) rattles[static_cast<std::size_t>(ball)] = {};
      continue;
    }
    if (e.balls.empty()) continue;
    const int ball = e.balls.front();
    Rattle& r = rattles[static_cast<std::size_t>(ball)];
    const bool goes_on = r.pocket == e.pocket && e.time - r.time <= kRattleGap;
    const double own = impact_gain(SoundKind::jaw_knock, e.speed);
    const double peak = goes_on ? std::min(own, kRattleFollow * r.peak) : own;
    SoundCue cue = event_cue(shot, SoundKind::jaw_knock, e.time, e.speed, e.where,
                             jaw_seed(e.pocket, cue_seed(SoundKind::jaw_knock, e.index, ball)));
    cue.level = peak / own;
    cues.push_back(cue);
    r = {e.pocket, e.time, peak};
  }
}

/// s: how finely a pocket fall is searched for its knocks (the fall's own integration step).
constexpr double kFallScan = 1.0 / 2000.0;
/// m/s: a change of the falling ball's horizontal velocity bigger than this is a knock on the liner.
constexpr double kKnockJump = 0.02;

/// The sounds of one ball dropping into a pocket: the fall over the lip as it enters, a knock for each
/// bounce off the liner (found where the fall's horizontal velocity jumps: only the liner changes it),
/// a knock as it lands at the bottom (at the speed it lands with), and its roll away from there.
void add_pocket_drop(const SoundSource& shot, const PocketDrop& drop, int index, std::vector<SoundCue>& cues) {
  const Timeline& timeline = shot.timeline;
  const Vec3 pocket = shot.scene.pockets[static_cast<std::size_t>(drop.pocket)].center;
  auto cue = [&](SoundKind kind, double t, double speed, const Vec3& where, int part) {
    cues.push_back(event_cue(shot, kind, t, speed, where, cue_seed(kind, index * 64 + part, drop.ball)));
  };
  const BallState entry = timeline.motion_state(drop.ball, drop.time);
  cue(SoundKind::pocket_fall, drop.time, std::hypot(entry.velocity.x(), entry.velocity.y()), entry.position, 0);
  double t = drop.time;
  BallState previous = entry;
  int part = 1;
  while (t < timeline.duration()) {
    t += kFallScan;
    const BallState s = timeline.motion_state(drop.ball, t);
    if (s.motion == Motion::pocketed) {
      cue(SoundKind::pocket_knock, t, std::abs(previous.velocity.z()), s.position, part++);
      cue(SoundKind::pocket_roll, t + 0.04, 0.25 + 0.3 * std::abs(previous.velocity.z()), pocket, part++);
      return;
    }
    const Vec3 jump(s.velocity.x() - previous.velocity.x(), s.velocity.y() - previous.velocity.y(), 0);
    if (s.motion == Motion::falling && previous.motion == Motion::falling && jump.norm() > kKnockJump)
      cue(SoundKind::pocket_knock, t, jump.norm() / (1 + kPocketWallRestitution), s.position, part++);
    previous = s;
  }
}

}  // namespace

double view_position(const CameraPose& camera, const Vec3& point, double fov_deg) {
  // The picture's frame as the front ends draw it (a camera on its look point looks straight down).
  return CameraView(camera, fov_deg).pan(point);
}

double distance_gain(double distance) { return kReferenceDistance / std::max(distance, kNearestDistance); }

Placement placement(const CameraPose& camera, const Vec3& where) {
  // Equal-power pan: the sum of the channels' powers is the same wherever the sound sits.
  const double pan = kPanWidth * view_position(camera, where, kCameraFovDeg);
  const double angle = (pan + 1.0) * std::numbers::pi / 4.0;
  const double gain = distance_gain((where - camera.location).norm());
  return {gain * std::cos(angle), gain * std::sin(angle), 1.0};
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
    if (e.type == EventType::ball_ball) {
      add_contact_clicks(shot, e, cues);
      continue;
    }
    const int ball = e.balls.empty() ? 0 : e.balls.front();
    // The tip's click follows the stick: with a stroke, at the ball speed a centre hit at the stroke's
    // speed gives (so an off-centre hit clicks as loud as a centre one of the same stroke).
    double speed = e.speed;
    // Each shot's click follows its own cue's stroke.
    const auto shot_index = static_cast<std::size_t>(std::max(e.shot, 0));
    const Stroke* stroke = nullptr;
    if (shot_index < shot.scene.cues.size() && shot.scene.cues[shot_index].stroke)
      stroke = &*shot.scene.cues[shot_index].stroke;
    if (e.type == EventType::cue && stroke) {
      const PhysicsParams& p = shot.scene.physics;
      speed = (1 + p.e_tip) * stroke->speed / (1 + p.ball_mass / p.cue_mass);
    }
    cues.push_back(event_cue(shot, kind, e.time, speed, e.where, cue_seed(kind, e.index, ball)));
  }
  add_jaw_knocks(shot, cues);
  const auto& drops = shot.timeline.pocket_drops();
  for (std::size_t i = 0; i < drops.size(); ++i) add_pocket_drop(shot, drops[i], static_cast<int>(i), cues);
  std::stable_sort(cues.begin(), cues.end(), [](const SoundCue& a, const SoundCue& b) { return a.time < b.time; });
  return cues;
}

void mix_cues(const std::vector<SoundCue>& cues, const PhysicsParams& physics, double lead, AudioBuffer& out,
              std::vector<float>* send) {
  const auto length = static_cast<long long>(out.left.size());
  for (const SoundCue& cue : cues) {
    std::vector<float> sound = synth_impact(cue.kind, cue.speed, cue.seed, physics, out.sample_rate);
    if (cue.level != 1)
      for (float& s : sound) s *= static_cast<float>(cue.level);
    // Equal-power pan: the sum of the channels' powers is the same wherever the sound sits.
    const double angle = (std::clamp(cue.pan, -1.0, 1.0) + 1.0) * std::numbers::pi / 4.0;
    const auto gain_left = static_cast<float>(cue.gain * std::cos(angle));
    const auto gain_right = static_cast<float>(cue.gain * std::sin(angle));
    const long long start = std::llround((cue.time - lead) * out.sample_rate);
    for (long long i = std::max(0LL, -start); i < static_cast<long long>(sound.size()); ++i) {
      const long long at = start + i;
      if (at >= length) break;
      out.left[static_cast<std::size_t>(at)] += gain_left * sound[static_cast<std::size_t>(i)];
      out.right[static_cast<std::size_t>(at)] += gain_right * sound[static_cast<std::size_t>(i)];
      if (send && static_cast<std::size_t>(at) < send->size())
        (*send)[static_cast<std::size_t>(at)] += sound[static_cast<std::size_t>(i)];
    }
  }
}

}  // namespace bsim
