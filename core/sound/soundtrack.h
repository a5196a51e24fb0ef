#pragma once
// The sound track: the impacts (sound_mix.h) and the rolling (rolling.h) heard from the camera, the
// room's reverberation and tone (room.h), optionally a music bed under them, at one calibrated level
// for every shot or brought to a loudness, its true peak kept under a ceiling (mastering.h).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "audio_buffer.h"
#include "frames.h"
#include "mastering.h"
#include "sound_mix.h"

namespace bsim {

/// LU: the music bed's integrated loudness under the effects' (their reverberation included).
inline constexpr double kMusicUnderEffects = 12.0;

struct SoundOptions {
  double lead = 0.0;       ///< s, sounds play this much before their event (default chosen in export)
  std::string music_path;  ///< optional music bed (any format libsndfile reads); empty for none
  SoundLevel level;        ///< how the finished track's level is set (default: calibrated)
};

/// Mixes the effects (and music) into exactly `sample_count` samples per channel.
/// Returns false with `error` set when the music file cannot be read.
bool mix_soundtrack(const SoundSource& shot, const SoundOptions& options, std::size_t sample_count, AudioBuffer& out,
                    std::string& error);

/// The movie a sound track follows when it is not the shot as it plays (frames.h): its segments, and
/// the replay's camera, which hears the replay's segment.
struct SoundMovie {
  const MovieTimeline* movie = nullptr;         ///< none: the shot as it plays
  const CameraScript* replay_camera = nullptr;  ///< hears the replay's segments; none: the shot's camera does
};

/// The sound track of the movie, `sample_count` samples per channel: each segment is the shot's
/// effects over its stretch of the simulation heard from its camera, a slowed segment (a replay)
/// played slower as a recording is (resample.h: half speed is an octave lower and twice as long,
/// its reverberation too); the music bed and the room tone run on unbroken under the whole movie.
/// For a movie of one segment at rate 1 it is mix_soundtrack()'s track.
bool mix_movie_soundtrack(const SoundSource& shot, const SoundMovie& movie, const SoundOptions& options,
                          std::size_t sample_count, AudioBuffer& out, std::string& error);

/// Writes 16-bit PCM stereo WAV. Returns false with `error` set on failure.
bool write_wav(const std::string& path, const AudioBuffer& audio, std::string& error);

}  // namespace bsim
