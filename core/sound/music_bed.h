#pragma once
// The optional music under the effects (the seed's "music sound track"): any file libsndfile reads,
// made stereo at the track's rate, looped or trimmed to the shot, faded in and out; its level is set
// by the sound track (soundtrack.h) from its loudness.
#include <cstddef>
#include <string>

#include "audio_buffer.h"

namespace bsim {

/// Fills `out` (sample rate already set) with exactly `sample_count` samples per channel of the
/// music in `path`. Returns false with `error` set ("PATH: reason") when the file cannot be read.
bool load_music_bed(const std::string& path, std::size_t sample_count, AudioBuffer& out, std::string& error);

/// Shapes a stereo buffer to `sample_count` samples: loops it with a short crossfade when too short,
/// trims it when too long, then fades in and out. Exposed for tests.
void fit_music(AudioBuffer& music, std::size_t sample_count);

}  // namespace bsim
