#pragma once
// What a camera sees of one ball: where it is while it can be seen, and a heading that turns smoothly
// (the frame of a `follow` camera: ball at the origin, moving along +x, z up).
#include <limits>
#include <optional>
#include <vector>

#include "timeline.h"

namespace bsim {

/// A later shot's stick striking the ball: from `from` (that shot's start, the ball at rest) the
/// ball's heading is the stick's, and its path after the strike turns from it as the first does from
/// the initial heading.
struct TrackStrike {
  double from = 0;     ///< s, the shot's start
  double time = 0;     ///< s, the strike
  double heading = 0;  ///< rad, the stick's
};

class BallTrack {
 public:
  /// `initial_heading_rad` is the heading before the ball first moves (the cue's heading for the
  /// struck ball); without one, the direction of its first motion, or +x if it never moves. `later`:
  /// the later shots' strikes of the ball, in time order. `timeline` must outlive the track.
  BallTrack(const Timeline& timeline, int ball, std::optional<double> initial_heading_rad,
            std::vector<TrackStrike> later = {});

  /// m, the ball's centre; while it is down in a pocket it stays at its last visible place (until a
  /// later shot puts it back on the bed, if one does).
  Vec3 position(double t) const;
  /// Unit horizontal vector: the direction of travel averaged over the recent path, so it turns
  /// smoothly through collisions, holds while the ball rests and never flickers as it stops.
  Vec3 heading(double t) const;
  /// rad, the heading as an angle counter-clockwise from +x (unwrapped, continuous in t).
  double heading_angle(double t) const;
  /// s, when the ball first drops out of sight into a pocket (infinity if it never does).
  double hidden_time() const { return hidden_.empty() ? std::numeric_limits<double>::infinity() : hidden_[0].begin; }

 private:
  BallState motion_state(double t) const { return timeline_->motion_state(ball_, t); }
  /// The ball's place at each sample (out of sight: where it was last seen); fills hidden_.
  std::vector<Vec3> sample_path(int samples);
  void add_resets(const std::vector<TrackStrike>& later);
  double arc_length(double t) const;
  double angle_integral(double s) const;

  /// Where the ball is out of sight: from `begin` (its last visible instant) until `end` (infinity:
  /// for good).
  struct Hidden {
    double begin = 0, end = 0;
  };
  /// Where the path resumes after a later strike: its arc length there and the stick's heading
  /// (unwrapped to the path's angles).
  struct Reset {
    double from = 0, arc = 0, angle = 0;
  };

  const Timeline* timeline_ = nullptr;
  int ball_ = 0;
  std::vector<Hidden> hidden_;
  std::vector<Reset> resets_;
  double initial_angle_ = 0;           ///< rad, the heading before any motion
  std::vector<double> arc_;            ///< m travelled (horizontally) up to sample i
  std::vector<double> knot_arc_;       ///< m, start of each stretch of constant direction
  std::vector<double> knot_integral_;  ///< rad*m, integral of the angle over arc length up to the knot
  std::vector<double> knot_angle_;     ///< rad, the direction over the stretch (unwrapped)
};

}  // namespace bsim
