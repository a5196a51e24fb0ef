#pragma once
// The last stage of the sound track: bringing it to a loudness (EBU R128, measured per ITU-R
// BS.1770-4 by loudness.h) and keeping its true peak under a ceiling with a look-ahead limiter.
#include <optional>

#include "audio_buffer.h"

namespace bsim {

/// LUFS, the integrated loudness the track is brought to unless told otherwise: the level AES TD1004
/// ("Loudness of audio streaming and network file playback") recommends for media played online.
inline constexpr double kDefaultLoudness = -16.0;
/// dBTP, the finished track's true peak stays at or under this: EBU R128 asks for at most -1 dBTP,
/// and half a dB more leaves room for meters that oversample differently and for 16-bit rounding.
inline constexpr double kTruePeakCeilingDb = -1.5;
/// dB, the most the track is raised to reach its loudness (a near-silent shot stays quiet).
inline constexpr double kMaxLoudnessGainDb = 60.0;
/// s: the limiter's look-ahead (its gain ramps down over twice this before a peak) and release.
inline constexpr double kLimiterLookahead = 0.0025;
inline constexpr double kLimiterRelease = 0.08;

/// Finishes `program` (the effects, their reverberation and any music) over the room's `floor`
/// (room tone, never scaled): with a `target`, scales `program` so that the sum has that integrated
/// loudness and limits its true peak to kTruePeakCeilingDb; with none, only scales the whole sum
/// down if its true peak would pass the ceiling. `program` ends holding the finished track.
void master(AudioBuffer& program, const AudioBuffer& floor, std::optional<double> target);

}  // namespace bsim
