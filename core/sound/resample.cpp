#include "resample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace bsim {

namespace {

/// Steps of the kernel's table per sample: the kernel between two is read by linear interpolation.
constexpr int kTableSteps = 512;
/// The pass band's share of the original's Nyquist frequency: the window's transition band lies
/// above it, so nothing near the top of the original comes back as an image.
constexpr double kPassBand = 0.9;

/// A Blackman-windowed sinc low-pass cutting at `cutoff` of the original's Nyquist frequency,
/// tabulated from -kResampleHalfWidth to +kResampleHalfWidth samples.
std::vector<double> kernel_table(double cutoff) {
  const int size = 2 * kResampleHalfWidth * kTableSteps + 1;
  std::vector<double> table(static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i) {
    const double d = static_cast<double>(i) / kTableSteps - kResampleHalfWidth;  // samples from the point
    const double x = std::numbers::pi * cutoff * d;
    const double sinc = d == 0 ? 1.0 : std::sin(x) / x;
    const double w = 2 * std::numbers::pi * (d / (2.0 * kResampleHalfWidth) + 0.5);  // 0 .. 2 pi over the width
    const double blackman = 0.42 - 0.5 * std::cos(w) + 0.08 * std::cos(2 * w);
    table[static_cast<std::size_t>(i)] = cutoff * sinc * blackman;
  }
  return table;
}

}  // namespace

std::vector<float> resample(const std::vector<float>& samples, double from, double step, std::size_t count) {
  const double cutoff = kPassBand * std::min(1.0, 1.0 / step);
  const std::vector<double> table = kernel_table(cutoff);
  const auto n = static_cast<long>(samples.size());
  std::vector<float> out(count, 0.0f);
  for (std::size_t j = 0; j < count; ++j) {
    const double at = from + static_cast<double>(j) * step;
    const auto centre = static_cast<long>(std::floor(at));
    double sum = 0;
    for (long i = std::max(0L, centre - kResampleHalfWidth + 1); i <= std::min(n - 1, centre + kResampleHalfWidth);
         ++i) {
      // The kernel at `at - i` samples, read from its table.
      const double position = (at - static_cast<double>(i) + kResampleHalfWidth) * kTableSteps;
      const auto k = static_cast<std::size_t>(position);
      if (k + 1 >= table.size()) continue;
      const double f = position - static_cast<double>(k);
      sum += samples[static_cast<std::size_t>(i)] * (table[k] + f * (table[k + 1] - table[k]));
    }
    out[j] = static_cast<float>(sum);
  }
  return out;
}

}  // namespace bsim
