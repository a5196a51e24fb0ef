#pragma once
// The rumble of balls rolling and sliding on the cloth, as a contact driven by the surfaces'
// roughness (rolling-sound synthesis after van den Doel, Kry & Pai, "FoleyAutomatic", SIGGRAPH 2001,
// and Rath & Rocchesso, "Continuous sonic feedback from a rolling ball", IEEE MultiMedia 12(2), 2005):
// noise low-passed at a cutoff that rises with speed, through the bed's low resonance, modulated once
// per turn of the ball by its own unevenness; a slipping contact adds the cloth's brighter hiss.
#include <cstdint>
#include <vector>

#include "audio_buffer.h"

namespace bsim {

struct SoundSource;

/// s between a rolling voice's control points; loudness, colour and place glide linearly between them.
inline constexpr double kRumbleStep = 0.001;

/// What a rolling voice does at one control point.
struct RumblePoint {
  double roll = 0;             ///< m/s, speed of the ball over the cloth (0 off the cloth)
  double slip = 0;             ///< m/s, speed the contact point slips over the cloth
  double left = 0, right = 0;  ///< gains of the direct sound (pan and distance)
  double send = 0;             ///< gain into the room's reverberation
};

/// RMS of a rolling ball's rumble at `roll` m/s before placement; 0 at rest, strictly growing.
double rumble_level(double roll);
/// RMS of the hiss of a contact slipping at `slip` m/s before placement; 0 without slip.
double slip_level(double slip);

/// Adds a rolling voice whose control point k lies at start + k * kRumbleStep to `out` (direct) and
/// `send` (reverberation, may be null). `muffle` (0..1) darkens it, for a ball rolling inside the
/// table. Adds nothing where the voice is silent, so a ball at rest adds exact zeros.
void render_rumble(const std::vector<RumblePoint>& points, double start, double ball_radius, std::uint64_t seed,
                   double muffle, AudioBuffer& out, std::vector<float>* send);

/// The rumble of every ball on the cloth over the whole shot, placed by the camera.
void mix_rolling(const SoundSource& shot, AudioBuffer& out, std::vector<float>* send);

}  // namespace bsim
