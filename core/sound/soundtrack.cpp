#include "soundtrack.h"

#include <sndfile.h>

#include <algorithm>
#include <cmath>

#include "loudness.h"
#include "music_bed.h"
#include "rolling.h"
#include "room.h"
#include "sound_mix.h"

namespace bsim {

namespace {

/// Seed of the room tone: the same room for every shot.
constexpr std::uint64_t kRoomSeed = 0x526f6f6d546f6e65ULL;

void add(AudioBuffer& to, const AudioBuffer& from, double gain) {
  for (std::size_t i = 0; i < to.left.size() && i < from.left.size(); ++i) {
    to.left[i] += static_cast<float>(gain * from.left[i]);
    to.right[i] += static_cast<float>(gain * from.right[i]);
  }
}

}  // namespace

bool mix_soundtrack(const SoundSource& shot, const SoundOptions& options, std::size_t sample_count, AudioBuffer& out,
                    std::string& error) {
  AudioBuffer music;
  music.sample_rate = kSampleRate;
  if (!options.music_path.empty() && !load_music_bed(options.music_path, sample_count, music, error)) return false;
  out.sample_rate = kSampleRate;
  out.left.assign(sample_count, 0.0f);
  out.right.assign(sample_count, 0.0f);
  std::vector<float> send(sample_count, 0.0f);
  mix_cues(sound_cues(shot), shot.timeline.physics(), options.lead, out, &send);
  mix_rolling(shot, out, &send);
  add_reverb(send, out);
  if (!options.music_path.empty()) {
    // The bed sits kMusicUnderEffects under the effects (or under the target if nothing is heard).
    // Calibrated, the effects are measured as they will be heard, at the calibrated gain.
    const std::optional<double> music_loudness = integrated_loudness(music);
    const std::optional<double> effects = integrated_loudness(out);
    const double heard = options.level.mode == LevelMode::calibrated ? kCalibratedGainDb : 0.0;
    const double wanted = (effects ? *effects - heard : options.level.loudness) - kMusicUnderEffects;
    if (music_loudness) add(out, music, from_db(wanted - *music_loudness));
  }
  master(out, room_tone(sample_count, kRoomSeed), options.level);
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
