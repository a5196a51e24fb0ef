#pragma once
// The last stage of the sound track: setting its level, by default one fixed, calibrated gain for
// every shot with a gentle compressor on the peaks (so a soft shot is quieter than a break), or on
// request bringing one shot to a loudness (EBU R128, measured per ITU-R BS.1770-4 by loudness.h);
// either way keeping its true peak under a ceiling with a look-ahead gain.
#include "audio_buffer.h"

namespace bsim {

/// LUFS: the level AES TD1004 ("Loudness of audio streaming and network file playback") recommends
/// for media played online. The calibrated gain brings the built-in break to it.
inline constexpr double kDefaultLoudness = -16.0;
/// dBTP, the finished track's true peak stays at or under this: EBU R128 asks for at most -1 dBTP,
/// and half a dB more leaves room for meters that oversample differently and for 16-bit rounding.
inline constexpr double kTruePeakCeilingDb = -1.5;
/// dB, the most the track is raised to reach its loudness (a near-silent shot stays quiet).
inline constexpr double kMaxLoudnessGainDb = 60.0;
/// dB, the one fixed gain every shot's effects get by default. Calibrated once on the built-in break
/// (`billiards-export --no-render`, measured with ffmpeg's ebur128=peak=true): with the compressor
/// below it measures -16 LUFS (kDefaultLoudness, within 0.5 LU). A click is far peakier than its
/// loudness (a recorded click's peak stands 18 dB over its first 100 ms), and the break's loudness is
/// that of its loudest half second, the rack's burst of clicks: its mix peaks about 27 dB above its
/// loudness. Recalibrate it when a sound's own level changes (tests/sound/test_sound.cpp checks the
/// break).
inline constexpr double kCalibratedGainDb = 15.5;
/// The calibrated level's compressor on the oversampled peak envelope, two soft-knee stages (the gain
/// computer of Giannoulis, Massberg & Reiss, "Digital dynamic range compressor design", JAES 2012),
/// each kCompressorKneeDb wide. Everything under kCompressorThresholdDb (dBFS) passes untouched: a
/// soft shot's hits (a 0.5 m/s click peaks near -14 dBFS after the gain). Above it (a 3 m/s click
/// comes out near -5 dBFS) a peak grows kCompressorRatio times slower, and above kCompressorUpperThresholdDb,
/// which only a break's burst reaches, kCompressorUpperRatio times slower again. The curve grows
/// strictly with the input, so a harder hit always peaks higher; only what would still pass the
/// true-peak ceiling (a shot harder than the break) is held at it. Chosen with the gain: the break
/// at -16 LUFS, its loudest peak under -2 dBTP, and a 3 m/s click still 10 dB over a 0.5 m/s one.
inline constexpr double kCompressorThresholdDb = -9.0;
inline constexpr double kCompressorRatio = 2.0;
inline constexpr double kCompressorUpperThresholdDb = -4.0;
inline constexpr double kCompressorUpperRatio = 8.0;
inline constexpr double kCompressorKneeDb = 6.0;
/// s: the look-ahead of the limiter and of the compressor (their gain ramps down over twice this
/// before a peak) and their release.
inline constexpr double kLimiterLookahead = 0.0025;
inline constexpr double kLimiterRelease = 0.08;

/// How the finished track's level is set.
enum class LevelMode {
  calibrated,  ///< one fixed gain for every shot (kCalibratedGainDb) and the gentle compressor
  normalised,  ///< this shot brought to `SoundLevel::loudness` (`--loudness LUFS`)
  off,         ///< the mix's own level (`--loudness off`)
};

struct SoundLevel {
  LevelMode mode = LevelMode::calibrated;
  double loudness = kDefaultLoudness;  ///< LUFS, the target when normalised
  bool operator==(const SoundLevel&) const = default;
};

/// "calibrated", "normalised" or "off".
const char* level_mode_name(LevelMode mode);

/// Finishes `program` (the effects, their reverberation and any music) over the room's `floor`
/// (room tone, never scaled). Calibrated: scales `program` by kCalibratedGainDb and compresses its
/// peaks, holding its true peak to kTruePeakCeilingDb. Normalised: scales `program` so that the sum
/// has the integrated loudness `level.loudness` and limits its true peak to kTruePeakCeilingDb. Off:
/// only scales the whole sum down if its true peak would pass the ceiling. `program` ends holding
/// the finished track.
void master(AudioBuffer& program, const AudioBuffer& floor, const SoundLevel& level);

}  // namespace bsim
