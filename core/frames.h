#pragma once
// How a shot is sampled into frames: frame k shows t = k / fps for every k with t < duration, so a
// shot of D seconds at F frames per second has D·F frames and plays for exactly D seconds, as long as
// its sound track. The movie, the animatic, trajectory.csv and camera.csv all use this one rule.
#include <algorithm>
#include <cmath>

namespace bsim {

/// The number of frames: ceil(duration · fps), at least one (a shot of no length still has a picture).
inline int frame_count(double duration, int fps) {
  return std::max(1, static_cast<int>(std::ceil(duration * fps - 1e-9)));
}
inline double frame_time(int frame, int fps) { return static_cast<double>(frame) / fps; }

}  // namespace bsim
