#include "soundtrack.h"

#include <sndfile.h>

#include <algorithm>
#include <cmath>

#include "music_bed.h"
#include "sound_mix.h"

namespace bsim {

namespace {

/// Highest sample level after mixing (-1 dBFS): a louder mix is scaled down as a whole, which keeps
/// every sound's loudness relative to the others.
constexpr float kCeiling = 0.891f;

}  // namespace

bool mix_soundtrack(const SoundSource& shot, const SoundOptions& options, std::size_t sample_count, AudioBuffer& out,
                    std::string& error) {
  out.sample_rate = kSampleRate;
  if (options.music_path.empty()) {
    out.left.assign(sample_count, 0.0f);
    out.right.assign(sample_count, 0.0f);
  } else if (!load_music_bed(options.music_path, sample_count, out, error)) {
    return false;
  }
  mix_cues(sound_cues(shot), shot.timeline.physics(), options.lead, out);
  float peak = 0.0f;
  for (std::size_t i = 0; i < sample_count; ++i) peak = std::max({peak, std::abs(out.left[i]), std::abs(out.right[i])});
  if (peak > kCeiling) {
    const float gain = kCeiling / peak;
    for (std::size_t i = 0; i < sample_count; ++i) {
      out.left[i] *= gain;
      out.right[i] *= gain;
    }
  }
  return true;
}

bool write_wav(const std::string& path, const AudioBuffer& audio, std::string& error) {
  SF_INFO info{};
  info.samplerate = audio.sample_rate;
  info.channels = 2;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  if (!file) {
    error = "cannot write " + path + ": " + sf_strerror(nullptr);
    return false;
  }
  // Quantised here, with rounding and clipping, so the bytes do not depend on libsndfile's converter.
  const std::size_t frames = std::min(audio.left.size(), audio.right.size());
  std::vector<short> pcm(2 * frames);
  auto quantise = [](float v) {
    return static_cast<short>(std::lround(std::clamp(static_cast<double>(v), -1.0, 1.0) * 32767.0));
  };
  for (std::size_t i = 0; i < frames; ++i) {
    pcm[2 * i] = quantise(audio.left[i]);
    pcm[2 * i + 1] = quantise(audio.right[i]);
  }
  const sf_count_t written = sf_writef_short(file, pcm.data(), static_cast<sf_count_t>(frames));
  const int closed = sf_close(file);
  if (written != static_cast<sf_count_t>(frames) || closed != 0) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace bsim
