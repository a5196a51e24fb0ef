#pragma once
// The room the table stands in: its quiet continuous tone (air, distant traffic, the building) and
// its short reverberation, the same for the whole shot.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "audio_buffer.h"

namespace bsim {

/// dBFS, RMS of each channel of the room tone on the finished track.
inline constexpr double kRoomToneDb = -54.0;
/// s, the room's reverberation time (RT60) at middle frequencies: a furnished room or a small club.
inline constexpr double kReverbTime = 0.45;
/// dB, energy of the reverberation relative to the direct sound of a source at the reference distance.
inline constexpr double kReverbLevelDb = -10.0;
/// s, delay of the reverberation after the direct sound (the first reflections off floor and walls).
inline constexpr double kReverbPreDelay = 0.006;

/// `sample_count` samples per channel of room tone at kRoomToneDb: pink noise (Kellet's filter) rolled
/// off above 2.5 kHz, as the NC curves of room noise fall (Beranek 1957), the two channels mostly
/// uncorrelated as in a diffuse field. Deterministic for a given seed.
AudioBuffer room_tone(std::size_t sample_count, std::uint64_t seed, int sample_rate = kSampleRate);

/// Adds the room's reverberation of the mono `send` into `out` (same length and rate): Schroeder's
/// parallel combs and series all-passes (Schroeder 1962) with damped combs (Moorer 1979), tuned as
/// Jezar's public-domain Freeverb (2000), each comb's feedback set for kReverbTime and the whole scaled
/// so that the reverberant energy is kReverbLevelDb under the direct sound's.
void add_reverb(const std::vector<float>& send, AudioBuffer& out);

}  // namespace bsim
