#pragma once
// The quietest stretch of a sound track: what "no digital silence" is checked with by the tests and
// reported by the sound benchmark.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "audio_buffer.h"

namespace bsim::test {

/// dBFS: the mean-square level of the quietest whole `window` seconds of `audio` (both channels),
/// stepping by a quarter window.
inline double quietest_window_db(const AudioBuffer& audio, double window) {
  const std::size_t n = std::min(audio.left.size(), audio.right.size());
  const auto length = static_cast<std::size_t>(std::llround(window * audio.sample_rate));
  const std::size_t step = std::max<std::size_t>(1, length / 4);
  if (length == 0 || n < length) return -200;
  double quietest = std::numeric_limits<double>::infinity();
  for (std::size_t start = 0; start + length <= n; start += step) {
    double sum = 0;
    for (std::size_t i = start; i < start + length; ++i)
      sum += 0.5 * (static_cast<double>(audio.left[i]) * audio.left[i] +
                    static_cast<double>(audio.right[i]) * audio.right[i]);
    quietest = std::min(quietest, sum / static_cast<double>(length));
  }
  return quietest > 0 ? 10 * std::log10(quietest) : -200;
}

}  // namespace bsim::test
