#pragma once
// Playing a recording at another speed, as a tape or a record played slower sounds: read between its
// samples by band-limited (windowed-sinc) interpolation, so half speed is an octave lower and twice
// as long, with no images of the original's upper half above the new band (Smith, "Digital Audio
// Resampling", 2002: the bandlimited interpolation of a signal from its samples).
#include <cstddef>
#include <vector>

namespace bsim {

/// Samples either side of the point read that the interpolation weighs.
inline constexpr int kResampleHalfWidth = 16;

/// `count` samples read from `samples` from (fractional) index `from` on, `step` indices apart: a step
/// of 0.5 plays them at half speed. Before the first sample and after the last there is silence. When
/// the step is over 1 (faster) the band is narrowed to the new rate's so nothing folds back.
std::vector<float> resample(const std::vector<float>& samples, double from, double step, std::size_t count);

}  // namespace bsim
