#pragma once
// What a camera sees of one ball: where it is while it can be seen, and a heading that turns smoothly
// (the frame of a `follow` camera: ball at the origin, moving along +x, z up).
#include <optional>
#include <vector>

#include "timeline.h"

namespace bsim {

class BallTrack {
 public:
  /// `initial_heading_rad` is the heading before the ball first moves (the cue's heading for the
  /// struck ball); without one, the direction of its first motion, or +x if it never moves.
  /// `timeline` must outlive the track.
  BallTrack(const Timeline& timeline, int ball, std::optional<double> initial_heading_rad);

  /// m, the ball's centre; once it has dropped below the bed it stays at its last visible place.
  Vec3 position(double t) const;
  /// Unit horizontal vector: the direction of travel averaged over the recent path, so it turns
  /// smoothly through collisions, holds while the ball rests and never flickers as it stops.
  Vec3 heading(double t) const;
  /// rad, the heading as an angle counter-clockwise from +x (unwrapped, continuous in t).
  double heading_angle(double t) const;
  /// s, when the ball drops out of sight into a pocket (infinity if it never does).
  double hidden_time() const { return hidden_time_; }

 private:
  BallState motion_state(double t) const { return timeline_->motion_state(ball_, t); }
  double arc_length(double t) const;
  double angle_integral(double s) const;

  const Timeline* timeline_ = nullptr;
  int ball_ = 0;
  double hidden_time_ = 0;
  double initial_angle_ = 0;           ///< rad, the heading before any motion
  std::vector<double> arc_;            ///< m travelled (horizontally) up to sample i
  std::vector<double> knot_arc_;       ///< m, start of each stretch of constant direction
  std::vector<double> knot_integral_;  ///< rad*m, integral of the angle over arc length up to the knot
  std::vector<double> knot_angle_;     ///< rad, the direction over the stretch (unwrapped)
};

}  // namespace bsim
