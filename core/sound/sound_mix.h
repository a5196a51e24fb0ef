#pragma once
// From the shot to sounds on the track: one cue per cue, ball-ball and ball-rail event and per
// ball landing in a pocket, panned by where it happens in the camera's view at that moment.
#include <cstdint>
#include <vector>

#include "audio_buffer.h"
#include "camera_script.h"
#include "physics_params.h"
#include "sound_synth.h"

namespace bsim {

/// What the sound track is made from: the shot's events, where they happen, and the camera that
/// hears them (all must outlive it).
struct SoundSource {
  const Scene& scene;
  const Timeline& timeline;
  const CameraScript& camera;
};

struct SoundCue {
  SoundKind kind = SoundKind::ball_ball;
  double time = 0;         ///< s, the instant of contact
  double speed = 0;        ///< m/s, what sets the loudness
  double pan = 0;          ///< -1 hard left .. +1 hard right
  std::uint64_t seed = 0;  ///< varies the modes from hit to hit, fixed per cue
};

/// Where `point` lies across the picture of a camera with this horizontal field of view: -1 at the
/// left edge, +1 at the right, clamped; points behind the camera go to the side they are on.
double view_position(const CameraPose& camera, const Vec3& point, double fov_deg);

/// The sound cues of a shot, in time order (events first, then pocket landings).
std::vector<SoundCue> sound_cues(const SoundSource& shot);

/// Adds every cue's sound, starting `lead` seconds before its time, into `out` (whose channels
/// already have their length); sounds that would start before 0 lose their head, past the end their tail.
void mix_cues(const std::vector<SoundCue>& cues, const PhysicsParams& physics, double lead, AudioBuffer& out);

}  // namespace bsim
