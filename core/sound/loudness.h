#pragma once
// Loudness and true peak as broadcasters measure them: ITU-R BS.1770-4 (K-weighting, 400 ms blocks
// overlapping by 75%, the absolute gate at -70 LUFS and the relative gate 10 LU under the ungated
// level; EBU R128 names the unit LUFS) and its Annex 2 (the true peak of the signal oversampled 4x).
#include <array>
#include <optional>
#include <vector>

#include "audio_buffer.h"

namespace bsim {

/// A biquad's coefficients, a0 = 1: y = b0 x + b1 x1 + b2 x2 - a1 y1 - a2 y2.
struct Biquad {
  std::array<double, 3> b{1, 0, 0};
  std::array<double, 2> a{0, 0};
};

/// The two stages of the K-weighting filter at `sample_rate`: the head's high shelf (+4 dB above
/// about 1.7 kHz) and the RLB high-pass (about 38 Hz). At 48 kHz they are the coefficients printed in
/// BS.1770-4; at other rates the same analogue prototypes through the bilinear transform.
std::array<Biquad, 2> k_weighting(int sample_rate);

/// LUFS, the gated integrated loudness of the stereo `audio` (both channels weighted 1); none when
/// no block passes the absolute gate (silence, or shorter than one 400 ms block).
std::optional<double> integrated_loudness(const AudioBuffer& audio);

/// Oversamples one channel 4x with a windowed-sinc interpolator and returns, for each input sample
/// n, the largest magnitude among the input sample and the three interpolated points that follow it.
std::vector<float> oversampled_peaks(const std::vector<float>& channel);

/// Linear: the true peak of `audio` (the largest oversampled magnitude of either channel).
double true_peak(const AudioBuffer& audio);

/// dB of a linear amplitude (-200 for 0).
double to_db(double amplitude);
/// Linear amplitude of a level in dB.
double from_db(double db);

}  // namespace bsim
