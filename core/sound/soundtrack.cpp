#include "soundtrack.h"

#include <sndfile.h>

#include <algorithm>
#include <cmath>

#include "loudness.h"
#include "music_bed.h"
#include "resample.h"
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

namespace {

/// The shot's effects as `shot.camera` hears them: the impacts, the rolling and the room's
/// reverberation of them, `sample_count` samples per channel from the simulation's start.
void mix_effects(const SoundSource& shot, double lead, std::size_t sample_count, AudioBuffer& out) {
  out.sample_rate = kSampleRate;
  out.left.assign(sample_count, 0.0f);
  out.right.assign(sample_count, 0.0f);
  std::vector<float> send(sample_count, 0.0f);
  mix_cues(sound_cues(shot), shot.timeline.physics(), lead, out, &send);
  mix_rolling(shot, out, &send);
  add_reverb(send, out);
}

/// Whether the movie is the shot as it plays: one segment from the start at rate 1, its own camera.
bool plain_movie(const SoundMovie& movie) {
  if (!movie.movie) return true;
  const auto& segments = movie.movie->segments();
  return segments.size() == 1 && segments[0].start == 0 && segments[0].rate == 1 && !segments[0].replay;
}

/// s over which a cut in the sound fades the sound that was cut out into the sound that follows: a
/// splice of two stretches of one recording, as an editor makes it, with no click.
constexpr double kCutFade = 0.01;

/// Fades, over kCutFade from movie sample `at`, the sound that would have followed the outgoing
/// stretch (from `outgoing` on in `heard`) into the incoming one (from `incoming` on), in `out`.
void crossfade_cut(const AudioBuffer& heard, std::size_t outgoing, std::size_t incoming, std::size_t at,
                   AudioBuffer& out) {
  const auto fade = static_cast<std::size_t>(std::llround(kCutFade * kSampleRate));
  for (std::size_t i = 0; i < fade && at + i < out.left.size(); ++i) {
    if (outgoing + i >= heard.left.size() || incoming + i >= heard.left.size()) break;
    const float in = static_cast<float>(i + 1) / static_cast<float>(fade + 1), away = 1.0f - in;
    out.left[at + i] = away * heard.left[outgoing + i] + in * heard.left[incoming + i];
    out.right[at + i] = away * heard.right[outgoing + i] + in * heard.right[incoming + i];
  }
}

/// Each segment of the movie from the effects heard by its camera: `main` for the plain segments,
/// the replay camera's (made here) for the replay's. A sound plays `lead` before its frame in a slowed
/// segment too.
void cut_movie_effects(const SoundSource& shot, const SoundMovie& movie, double lead, const AudioBuffer& main,
                       AudioBuffer& out) {
  const auto& segments = movie.movie->segments();
  AudioBuffer replay;
  if (movie.replay_camera) {
    // Heard up to a second past the last replayed instant: what comes later is never played.
    double until = 0;
    for (const MovieSegment& segment : segments)
      if (segment.replay) until = std::max(until, segment.end + 1.0);
    const auto count = std::min(main.left.size(), static_cast<std::size_t>(std::llround(until * kSampleRate)));
    mix_effects({shot.scene, shot.timeline, *movie.replay_camera}, lead, count, replay);
  }
  for (std::size_t j = 0; j < segments.size(); ++j) {
    const MovieSegment& segment = segments[j];
    const AudioBuffer& heard = segment.replay && movie.replay_camera ? replay : main;
    const auto at = static_cast<std::size_t>(std::llround(movie.movie->segment_begin(j) * kSampleRate));
    const std::size_t count = std::min(static_cast<std::size_t>(std::llround(segment.length() * kSampleRate)),
                                       out.left.size() - std::min(at, out.left.size()));
    if (segment.rate == 1) {  // as it plays: the samples themselves
      const auto from = static_cast<std::size_t>(std::llround(segment.start * kSampleRate));
      for (std::size_t i = 0; i < count && from + i < heard.left.size(); ++i) {
        out.left[at + i] = heard.left[from + i];
        out.right[at + i] = heard.right[from + i];
      }
      if (j > 0 && !segments[j - 1].replay && segments[j - 1].rate == 1 && !segment.replay)
        crossfade_cut(heard, static_cast<std::size_t>(std::llround(segments[j - 1].end * kSampleRate)), from, at, out);
      continue;
    }
    // Slowed: the recording read from where it holds the segment's first frame's sound, `lead` ahead.
    const double from = (segment.start - lead * (1 - segment.rate)) * kSampleRate;
    const std::vector<float> left = resample(heard.left, from, segment.rate, count);
    const std::vector<float> right = resample(heard.right, from, segment.rate, count);
    std::copy(left.begin(), left.end(), out.left.begin() + static_cast<std::ptrdiff_t>(at));
    std::copy(right.begin(), right.end(), out.right.begin() + static_cast<std::ptrdiff_t>(at));
  }
}

}  // namespace

bool mix_soundtrack(const SoundSource& shot, const SoundOptions& options, std::size_t sample_count, AudioBuffer& out,
                    std::string& error) {
  return mix_movie_soundtrack(shot, {}, options, sample_count, out, error);
}

bool mix_movie_soundtrack(const SoundSource& shot, const SoundMovie& movie, const SoundOptions& options,
                          std::size_t sample_count, AudioBuffer& out, std::string& error) {
  AudioBuffer music;
  music.sample_rate = kSampleRate;
  if (!options.music_path.empty() && !load_music_bed(options.music_path, sample_count, music, error)) return false;
  if (plain_movie(movie)) {
    mix_effects(shot, options.lead, sample_count, out);
  } else {
    AudioBuffer main;
    const auto simulated = static_cast<std::size_t>(std::llround(shot.timeline.duration() * kSampleRate));
    mix_effects(shot, options.lead, simulated, main);
    out.sample_rate = kSampleRate;
    out.left.assign(sample_count, 0.0f);
    out.right.assign(sample_count, 0.0f);
    cut_movie_effects(shot, movie, options.lead, main, out);
  }
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
