#pragma once
// How a shot is sampled into frames: frame k shows t = k / fps, from 0 to the duration inclusive.
#include <cmath>

namespace bsim {

inline int frame_count(double duration, int fps) { return static_cast<int>(std::floor(duration * fps + 1e-9)) + 1; }
inline double frame_time(int frame, int fps) { return static_cast<double>(frame) / fps; }

}  // namespace bsim
