#pragma once
// A stereo buffer of samples: what the synthesis, the music bed and the mix fill, and the WAV holds.
#include <vector>

namespace bsim {

/// Sound track sample rate, Hz.
inline constexpr int kSampleRate = 48000;

struct AudioBuffer {
  int sample_rate = kSampleRate;
  std::vector<float> left, right;  ///< [-1, 1]
};

}  // namespace bsim
