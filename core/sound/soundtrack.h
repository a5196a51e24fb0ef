#pragma once
// The sound track: one synthesised sound per cue, ball-ball, ball-rail event and pocket drop,
// panned by where the event lies in the camera's view, optionally over a music bed.
#include <cstddef>
#include <string>
#include <vector>

#include "audio_buffer.h"
#include "sound_mix.h"

namespace bsim {

struct SoundOptions {
  double lead = 0.0;       ///< s, sounds play this much before their event (default chosen in export)
  std::string music_path;  ///< optional music bed (any format libsndfile reads); empty for none
};

/// Mixes the effects (and music) into exactly `sample_count` samples per channel.
/// Returns false with `error` set when the music file cannot be read.
bool mix_soundtrack(const SoundSource& shot, const SoundOptions& options, std::size_t sample_count, AudioBuffer& out,
                    std::string& error);

/// Writes 16-bit PCM stereo WAV. Returns false with `error` set on failure.
bool write_wav(const std::string& path, const AudioBuffer& audio, std::string& error);

}  // namespace bsim
