#include "music_bed.h"

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bsim {

namespace {

constexpr double kLoopCrossfade = 0.25;  ///< s, overlap where a short piece meets its own start
constexpr double kFadeIn = 1.0;          ///< s
constexpr double kFadeOut = 2.0;         ///< s
constexpr double kHalfPi = 1.5707963267948966;

/// Linear-interpolation resampling; enough for a bed kept well under the effects.
std::vector<float> convert_rate(const std::vector<float>& in, int from_rate, int to_rate) {
  if (from_rate == to_rate || in.empty()) return in;
  const double step = static_cast<double>(from_rate) / to_rate;
  const auto n = static_cast<std::size_t>(std::floor((static_cast<double>(in.size()) - 1) / step)) + 1;
  std::vector<float> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) * step;
    const auto k = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(k);
    const float a = in[k], b = k + 1 < in.size() ? in[k + 1] : in[k];
    out[i] = static_cast<float>(a + f * (b - a));
  }
  return out;
}

void fit_channel(std::vector<float>& channel, std::size_t count, std::size_t crossfade) {
  const std::size_t length = channel.size();
  if (length == 0) {
    channel.assign(count, 0.0f);
    return;
  }
  if (length >= count) {
    channel.resize(count);
    return;
  }
  crossfade = std::min(crossfade, length / 4);
  const std::size_t period = length - crossfade;
  std::vector<float> out(count, 0.0f);
  for (std::size_t start = 0; start < count; start += period) {
    const bool first = start == 0, last = start + length >= count;
    for (std::size_t i = 0; i < length && start + i < count; ++i) {
      // Equal-power crossfade: the end and the start of a piece are unrelated, so their powers add.
      double w = 1.0;
      if (!first && i < crossfade) w = std::sin(kHalfPi * static_cast<double>(i) / static_cast<double>(crossfade));
      if (!last && i >= length - crossfade)
        w = std::sin(kHalfPi * static_cast<double>(length - i) / static_cast<double>(crossfade));
      out[start + i] += static_cast<float>(w) * channel[i];
    }
  }
  channel = std::move(out);
}

}  // namespace

void fit_music(AudioBuffer& music, std::size_t sample_count) {
  const auto rate = static_cast<double>(music.sample_rate);
  const auto crossfade = static_cast<std::size_t>(kLoopCrossfade * rate);
  fit_channel(music.left, sample_count, crossfade);
  fit_channel(music.right, sample_count, crossfade);
  const std::size_t fade_in = std::min(static_cast<std::size_t>(kFadeIn * rate), sample_count / 4);
  const std::size_t fade_out = std::min(static_cast<std::size_t>(kFadeOut * rate), sample_count / 4);
  for (std::size_t i = 0; i < fade_in; ++i) {
    const auto w = static_cast<float>(static_cast<double>(i) / static_cast<double>(fade_in));
    music.left[i] *= w;
    music.right[i] *= w;
  }
  for (std::size_t i = 0; i < fade_out; ++i) {
    const auto w = static_cast<float>(static_cast<double>(i) / static_cast<double>(fade_out));
    music.left[sample_count - 1 - i] *= w;
    music.right[sample_count - 1 - i] *= w;
  }
}

bool load_music_bed(const std::string& path, std::size_t sample_count, AudioBuffer& out, std::string& error) {
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (!file) {
    // libsndfile words a missing file "System error : ..."; the reason alone reads better.
    std::string reason = sf_strerror(nullptr);
    if (reason.starts_with("System error : ")) reason.erase(0, 15);
    error = "cannot read the music file '" + path + "': " + reason;
    return false;
  }
  const auto channels = static_cast<std::size_t>(std::max(info.channels, 1));
  std::vector<float> left, right, block(4096 * channels);
  for (;;) {
    const sf_count_t got = sf_readf_float(file, block.data(), 4096);
    if (got <= 0) break;
    for (sf_count_t i = 0; i < got; ++i) {
      const float* frame = &block[static_cast<std::size_t>(i) * channels];
      left.push_back(frame[0]);
      right.push_back(channels > 1 ? frame[1] : frame[0]);
    }
  }
  sf_close(file);
  if (left.empty()) {
    error = path + ": the music file holds no sound";
    return false;
  }
  out.left = convert_rate(left, info.samplerate, out.sample_rate);
  out.right = convert_rate(right, info.samplerate, out.sample_rate);
  fit_music(out, sample_count);
  return true;
}

}  // namespace bsim
