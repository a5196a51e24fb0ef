#pragma once
// The box filter over the open shutter that the POV-Ray frames' motion blur stands for, worked out in
// C++: what share of the shutter a swept stick or a ball's streak covers a point. The shared include's
// CueSweep/StickCover and BallStreak compute the same in POV-Ray; the tests hold them to these.
#include <algorithm>
#include <cmath>
#include <vector>

#include "pov_frame.h"

namespace bsim::test {

/// What share of the open shutter a ball of `radius` covers the point of a streak's piece at
/// (`along`, `across`) (m, in the picture, from the piece's start, along it and across it) when the
/// piece is `length` long and weighted by `weight` (its share of the shutter's time over its length):
/// weight times the length of the ball's centre line within the piece that lies within the ball's
/// chord through the point. Integrated over the picture it is weight x length x pi radius^2: a
/// streak's pieces together are one full ball. BallStreak in the shared include computes the same.
inline double streak_cover(double along, double across, double length, double weight, double radius) {
  const double half = std::sqrt(std::max(radius * radius - across * across, 0.0));
  return std::clamp(weight * (std::min(along + half, length) - std::max(along - half, 0.0)), 0.0, 1.0);
}

/// What share of the open shutter a stick `length` long that goes its way in `pieces` covers the
/// point `along` m along its axis (as in StickTravel): for each piece, its share times the part of
/// its way during which the point lies between the tip and the butt (the tip within [along - length,
/// along]), a piece shorter than kStreakLeast taken as that long. CueSweep in the shared include
/// computes the same.
inline double stick_cover(double along, const std::vector<StickTravel>& pieces, double length) {
  double cover = 0;
  for (const StickTravel& piece : pieces) {
    const double low = std::min(piece.from, piece.to),
                 high = std::max(std::max(piece.from, piece.to), low + kStreakLeast);
    cover += piece.share * std::max(0.0, std::min(high, along) - std::max(low, along - length)) / (high - low);
  }
  return std::clamp(cover, 0.0, 1.0);
}

}  // namespace bsim::test
