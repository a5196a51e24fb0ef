#include "mastering.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

#include "loudness.h"

namespace bsim {

namespace {

/// Sliding minimum of `x` over [n - half, n + half] (a monotonic queue, linear time).
std::vector<double> sliding_min(const std::vector<double>& x, std::size_t half) {
  const std::size_t n = x.size();
  std::vector<double> out(n);
  std::deque<std::size_t> queue;
  std::size_t next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (; next < n && next <= i + half; ++next) {
      while (!queue.empty() && x[queue.back()] >= x[next]) queue.pop_back();
      queue.push_back(next);
    }
    while (queue.front() + half < i) queue.pop_front();
    out[i] = x[queue.front()];
  }
  return out;
}

/// Centred moving average over [n - half, n + half] (the edges average what there is).
std::vector<double> moving_average(const std::vector<double>& x, std::size_t half) {
  const std::size_t n = x.size();
  std::vector<double> prefix(n + 1, 0.0), out(n);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + x[i];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i >= half ? i - half : 0, b = std::min(n, i + half + 1);
    out[i] = (prefix[b] - prefix[a]) / static_cast<double>(b - a);
  }
  return out;
}

/// Smooths a sample-by-sample gain `need` without ever exceeding it: each sample's need is held
/// over the look-ahead on both sides and then averaged over it (each averaged value is a minimum
/// over a span holding it), then released with a one-pole recovery; returned times `gain`.
std::vector<double> smooth_gain(const std::vector<double>& need, double gain, int rate) {
  const std::size_t n = need.size();
  const auto half = static_cast<std::size_t>(std::llround(kLimiterLookahead * rate));
  std::vector<double> smooth = moving_average(sliding_min(need, half), half);
  const double recover = 1 - std::exp(-1 / (kLimiterRelease * rate));
  double r = 1;
  for (std::size_t i = 0; i < n; ++i) {
    r = std::min(smooth[i], r + (1 - r) * recover);
    smooth[i] = gain * r;
  }
  return smooth;
}

/// The limiter's gain for the program scaled by `gain`: at every sample at most what keeps the
/// oversampled peak `envelope` (of the unscaled program) plus the floor's peak under `ceiling`.
std::vector<double> limiter_gain(const std::vector<double>& envelope, double gain, double headroom, int rate) {
  const std::size_t n = envelope.size();
  std::vector<double> need(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double peak = gain * envelope[i];
    need[i] = peak > headroom ? headroom / peak : 1.0;
  }
  return smooth_gain(need, gain, rate);
}

/// dB: one soft-knee stage's output for an input at `x` dB: above `threshold` it grows `ratio` times
/// slower, entering over kCompressorKneeDb (Giannoulis, Massberg & Reiss 2012, eq. 4). Strictly
/// growing in x.
double soft_knee(double x, double threshold, double ratio) {
  const double over = x - threshold, half_knee = kCompressorKneeDb / 2;
  if (over > half_knee) return threshold + over / ratio;
  if (over <= -half_knee) return x;
  const double into = over + half_knee;
  return x + (1 / ratio - 1) * into * into / (2 * kCompressorKneeDb);
}

/// dB: the compressor's output level for a peak at `x` dBFS: the gentle stage, then the steeper one
/// for the break's loudest, never over `ceiling_db`. Strictly growing in x up to the ceiling.
double compressed_level(double x, double ceiling_db) {
  const double gentle = soft_knee(x, kCompressorThresholdDb, kCompressorRatio);
  return std::min(soft_knee(gentle, kCompressorUpperThresholdDb, kCompressorUpperRatio), ceiling_db);
}

/// The calibrated level's gain: kCalibratedGainDb, times the compressor's gain for the program's
/// oversampled peak `envelope` (the floor's peak taken off the ceiling), smoothed as the limiter's.
std::vector<double> compressor_gain(const std::vector<double>& envelope, double headroom, int rate) {
  const double gain = from_db(kCalibratedGainDb), ceiling_db = to_db(headroom);
  std::vector<double> need(envelope.size());
  for (std::size_t i = 0; i < envelope.size(); ++i) {
    const double x = to_db(gain * envelope[i]);
    need[i] = from_db(compressed_level(x, ceiling_db) - x);
  }
  return smooth_gain(need, gain, rate);
}

void mix_into(const AudioBuffer& program, const std::vector<double>& gain, const AudioBuffer& floor, AudioBuffer& out) {
  const std::size_t n = program.left.size();
  out.sample_rate = program.sample_rate;
  out.left.resize(n);
  out.right.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.left[i] = static_cast<float>(gain[i] * program.left[i] + (i < floor.left.size() ? floor.left[i] : 0.0f));
    out.right[i] = static_cast<float>(gain[i] * program.right[i] + (i < floor.right.size() ? floor.right[i] : 0.0f));
  }
}

void scale(AudioBuffer& audio, double gain) {
  for (float& v : audio.left) v = static_cast<float>(v * gain);
  for (float& v : audio.right) v = static_cast<float>(v * gain);
}

}  // namespace

const char* level_mode_name(LevelMode mode) {
  switch (mode) {
    case LevelMode::calibrated: return "calibrated";
    case LevelMode::normalised: return "normalised";
    case LevelMode::off: return "off";
  }
  return "?";
}

namespace {

/// Brings `program` plus `floor` to the integrated loudness `target` into `out`, limited.
void normalise(const AudioBuffer& program, const std::vector<double>& envelope, double headroom,
               const AudioBuffer& floor, double target, AudioBuffer& out) {
  const std::optional<double> measured = integrated_loudness(program);
  if (!measured) {
    mix_into(program, std::vector<double>(envelope.size(), 1.0), floor, out);
    return;
  }
  double gain_db = std::min(target - *measured, kMaxLoudnessGainDb);
  // What the limiter takes off lowers the loudness: measure again and correct. Each step divides the
  // shortfall by how much the last step of gain raised the loudness (the secant), since the harder
  // the limiter works the less a dB of gain brings.
  double previous_gain = 0, previous_loudness = *measured;
  for (int round = 0; round < 12; ++round) {
    mix_into(program, limiter_gain(envelope, from_db(gain_db), headroom, program.sample_rate), floor, out);
    const std::optional<double> loudness = integrated_loudness(out);
    if (!loudness || std::abs(*loudness - target) < 0.05) break;
    const double step = gain_db - previous_gain;
    const double slope = std::abs(step) > 1e-9 ? std::clamp((*loudness - previous_loudness) / step, 0.2, 1.0) : 1.0;
    const double next = std::min(gain_db + (target - *loudness) / slope, kMaxLoudnessGainDb);
    if (next == gain_db) break;
    previous_gain = gain_db;
    previous_loudness = *loudness;
    gain_db = next;
  }
}

}  // namespace

void master(AudioBuffer& program, const AudioBuffer& floor, const SoundLevel& level) {
  const double ceiling = from_db(kTruePeakCeilingDb);
  const std::size_t n = std::min(program.left.size(), program.right.size());
  AudioBuffer out;
  if (level.mode == LevelMode::off) {
    mix_into(program, std::vector<double>(n, 1.0), floor, out);
  } else {
    std::vector<double> envelope(n);
    const std::vector<float> left = oversampled_peaks(program.left), right = oversampled_peaks(program.right);
    for (std::size_t i = 0; i < n; ++i) envelope[i] = std::max(left[i], right[i]);
    const double headroom = std::max(0.1 * ceiling, ceiling - true_peak(floor));
    if (level.mode == LevelMode::normalised)
      normalise(program, envelope, headroom, floor, level.loudness, out);
    else
      mix_into(program, compressor_gain(envelope, headroom, program.sample_rate), floor, out);
  }
  // A last guard: the gain's own movement can lift a peak between samples a hair.
  const double peak = true_peak(out);
  if (peak > ceiling) scale(out, ceiling / peak);
  program = std::move(out);
}

}  // namespace bsim
