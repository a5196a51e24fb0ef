#pragma once
// From the shot to sounds on the track: one cue per cue stroke, per contact of a ball-ball event, per
// ball-rail event and per ball-jaw event (a rattle's knocks heard as one rattle), and for each ball
// dropping into a pocket its fall, its knocks against the pocket's liner and its roll away; each
// placed by where it happens in the camera's view at that moment (pan) and how far from the camera
// (distance).
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
  double gain = 1;         ///< the direct sound's gain for the distance from the camera
  double level = 1;        ///< scales the sound itself, direct and in the room: a rattle's later knocks
};

/// s: a ball's knocks on one pocket's jaws, each within this of the one before and with nothing else
/// touching the ball between them, make one rattle. Across a throat 5 to 8 cm wide between the facings a
/// ball knocks again within it down to about 0.15 m/s; slower, it has all but come to rest in the jaws.
inline constexpr double kRattleGap = 0.5;
/// Each later knock of a rattle peaks at most this share of the one before it (about 3 dB softer): the
/// rattle dies away as one sound, never a row of equal knocks.
inline constexpr double kRattleFollow = 0.7;

/// m: a sound this far from the camera is heard at its own level; nearer ones are louder (down to
/// kNearestDistance), further ones quieter, as 1 / distance (the inverse-square law of power).
inline constexpr double kReferenceDistance = 2.0;
inline constexpr double kNearestDistance = 1.0;

/// How a sound at one place is heard from one camera pose: the direct sound's gains on each
/// channel (equal-power pan by view_position, times the distance gain) and the gain into the room's
/// reverberation (the diffuse field does not fall with distance, so far sounds are heard wetter).
struct Placement {
  double left = 0, right = 0;
  double send = 1;
};

/// The direct sound's gain at `distance` m from the camera.
double distance_gain(double distance);

/// Placement of a sound at `where`, heard from `camera` (pan scaled by the picture's edges, as cues are).
Placement placement(const CameraPose& camera, const Vec3& where);

/// Where `point` lies across the picture of a camera with this horizontal field of view: -1 at the
/// left edge, +1 at the right, clamped; points behind the camera go to the side they are on.
double view_position(const CameraPose& camera, const Vec3& point, double fov_deg);

/// The sound cues of a shot, in time order (events first, then pocket landings).
std::vector<SoundCue> sound_cues(const SoundSource& shot);

/// Adds every cue's sound, starting `lead` seconds before its time, into `out` (whose channels
/// already have their length) and, unscaled by distance, into the mono reverberation `send` when
/// given; sounds that would start before 0 lose their head, past the end their tail.
void mix_cues(const std::vector<SoundCue>& cues, const PhysicsParams& physics, double lead, AudioBuffer& out,
              std::vector<float>* send = nullptr);

}  // namespace bsim
