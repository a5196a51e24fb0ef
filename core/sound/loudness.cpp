#include "loudness.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace bsim {

namespace {

constexpr double kBlock = 0.4;              ///< s, gating block (BS.1770-4, 2.1)
constexpr double kBlockStep = 0.1;          ///< s, 75% overlap
constexpr double kAbsoluteGate = -70.0;     ///< LUFS
constexpr double kRelativeGate = -10.0;     ///< LU under the loudness of the blocks above the absolute gate
constexpr double kLoudnessOffset = -0.691;  ///< the constant of BS.1770-4's loudness formula

/// Half the interpolator's length in input samples (32 taps per phase).
constexpr int kHalfTaps = 16;
constexpr int kOversample = 4;

/// Runs one biquad over `x` in place (direct form I, in double).
void filter(const Biquad& q, std::vector<double>& x) {
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  for (double& v : x) {
    const double y = q.b[0] * v + q.b[1] * x1 + q.b[2] * x2 - q.a[0] * y1 - q.a[1] * y2;
    x2 = x1;
    x1 = v;
    y2 = y1;
    y1 = y;
    v = y;
  }
}

/// The K-weighted square of each sample of one channel.
std::vector<double> weighted_power(const std::vector<float>& channel, int sample_rate) {
  std::vector<double> x(channel.begin(), channel.end());
  for (const Biquad& q : k_weighting(sample_rate)) filter(q, x);
  for (double& v : x) v *= v;
  return x;
}

double bessel_i0(double x) {
  // Power series of the modified Bessel function of the first kind, order 0.
  double sum = 1, term = 1;
  for (int k = 1; k < 40; ++k) {
    term *= (x / (2 * k)) * (x / (2 * k));
    sum += term;
  }
  return sum;
}

/// The interpolator's taps for the point `phase`/4 past a sample: a sinc cut off at the input's
/// Nyquist frequency under a Kaiser window (beta 8), normalised to unit gain at 0 Hz.
std::array<std::array<double, 2 * kHalfTaps>, kOversample> interpolator() {
  std::array<std::array<double, 2 * kHalfTaps>, kOversample> taps{};
  constexpr double kBeta = 8.0;
  for (int p = 1; p < kOversample; ++p) {
    double sum = 0;
    for (int j = 0; j < 2 * kHalfTaps; ++j) {
      // Tap j weighs input sample n + j - kHalfTaps + 1 for the point n + p/4.
      const double x = static_cast<double>(p) / kOversample - (j - kHalfTaps + 1);
      const double sinc = x == 0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
      const double r = x / kHalfTaps;
      const double window = std::abs(r) < 1 ? bessel_i0(kBeta * std::sqrt(1 - r * r)) / bessel_i0(kBeta) : 0.0;
      taps[static_cast<std::size_t>(p)][static_cast<std::size_t>(j)] = sinc * window;
      sum += sinc * window;
    }
    for (double& t : taps[static_cast<std::size_t>(p)]) t /= sum;
  }
  return taps;
}

}  // namespace

std::array<Biquad, 2> k_weighting(int sample_rate) {
  // Analogue prototypes whose bilinear transforms at 48 kHz give BS.1770-4's coefficients (the
  // parameters fitted to them by Kokemueller's libebur128): a high shelf and a second-order high-pass.
  std::array<Biquad, 2> stages;
  {
    const double f0 = 1681.974450955533, gain_db = 3.999843853973347, q = 0.7071752369554196;
    const double k = std::tan(std::numbers::pi * f0 / sample_rate);
    const double vh = std::pow(10.0, gain_db / 20), vb = std::pow(vh, 0.4996667741545416);
    const double a0 = 1 + k / q + k * k;
    stages[0].b = {(vh + vb * k / q + k * k) / a0, 2 * (k * k - vh) / a0, (vh - vb * k / q + k * k) / a0};
    stages[0].a = {2 * (k * k - 1) / a0, (1 - k / q + k * k) / a0};
  }
  {
    const double f0 = 38.13547087602444, q = 0.5003270373238773;
    const double k = std::tan(std::numbers::pi * f0 / sample_rate);
    const double a0 = 1 + k / q + k * k;
    stages[1].b = {1, -2, 1};
    stages[1].a = {2 * (k * k - 1) / a0, (1 - k / q + k * k) / a0};
  }
  return stages;
}

std::optional<double> integrated_loudness(const AudioBuffer& audio) {
  const std::size_t n = std::min(audio.left.size(), audio.right.size());
  const auto block = static_cast<std::size_t>(std::llround(kBlock * audio.sample_rate));
  const auto step = static_cast<std::size_t>(std::llround(kBlockStep * audio.sample_rate));
  if (n < block || block == 0) return std::nullopt;
  const std::vector<double> left = weighted_power(audio.left, audio.sample_rate);
  const std::vector<double> right = weighted_power(audio.right, audio.sample_rate);
  // Running sums give each block's mean square; blocks start every 100 ms and lie wholly inside.
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + left[i] + right[i];
  std::vector<double> blocks;
  for (std::size_t start = 0; start + block <= n; start += step)
    blocks.push_back((prefix[start + block] - prefix[start]) / static_cast<double>(block));
  auto loudness = [](double mean_square) { return kLoudnessOffset + 10 * std::log10(mean_square); };
  auto gated_mean = [&](double threshold) {
    double sum = 0;
    std::size_t count = 0;
    for (double z : blocks)
      if (z > 0 && loudness(z) > threshold) {
        sum += z;
        ++count;
      }
    return count == 0 ? 0.0 : sum / static_cast<double>(count);
  };
  const double absolute = gated_mean(kAbsoluteGate);
  if (absolute <= 0) return std::nullopt;
  const double relative = gated_mean(loudness(absolute) + kRelativeGate);
  return loudness(relative);
}

std::vector<float> oversampled_peaks(const std::vector<float>& channel) {
  static const auto taps = interpolator();
  const auto n = static_cast<long long>(channel.size());
  std::vector<float> peaks(channel.size());
  for (long long i = 0; i < n; ++i) {
    double peak = std::abs(channel[static_cast<std::size_t>(i)]);
    const long long first = i - kHalfTaps + 1;
    for (int p = 1; p < kOversample; ++p) {
      const auto& t = taps[static_cast<std::size_t>(p)];
      double v = 0;
      const int j0 = static_cast<int>(std::max(0LL, -first));
      const int j1 = static_cast<int>(std::min<long long>(2 * kHalfTaps, n - first));
      for (int j = j0; j < j1; ++j) v += t[static_cast<std::size_t>(j)] * channel[static_cast<std::size_t>(first + j)];
      peak = std::max(peak, std::abs(v));
    }
    peaks[static_cast<std::size_t>(i)] = static_cast<float>(peak);
  }
  return peaks;
}

double true_peak(const AudioBuffer& audio) {
  double peak = 0;
  for (const std::vector<float>* channel : {&audio.left, &audio.right})
    for (float p : oversampled_peaks(*channel)) peak = std::max(peak, static_cast<double>(p));
  return peak;
}

double to_db(double amplitude) { return amplitude > 0 ? 20 * std::log10(amplitude) : -200; }

double from_db(double db) { return std::pow(10.0, db / 20); }

}  // namespace bsim
