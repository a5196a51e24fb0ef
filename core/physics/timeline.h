#pragma once
// The simulated shot: every ball's exact state at any time, and the numbered events.
// Everything downstream (camera, stick, sound, frames, preview) reads only this.
#include <vector>

#include "event.h"
#include "physics_params.h"

namespace bsim {

struct Scene;

/// A stretch of one ball's motion in closed form: from `start` at `t0` until the next segment.
struct MotionSegment {
  double t0 = 0;    ///< s
  BallState start;  ///< state at t0
  int pocket = -1;  ///< falling/pocketed: the pocket it drops into
};

class Timeline {
 public:
  Timeline() = default;
  Timeline(const Scene& scene, std::vector<std::vector<MotionSegment>> segments, std::vector<Event> events,
           std::vector<PocketDrop> drops);

  /// s, time of the end event.
  double duration() const { return events_.empty() ? 0.0 : events_.back().time; }
  /// s, time of the cue event.
  double cue_time() const;
  const std::vector<Event>& events() const { return events_; }
  const std::vector<PocketDrop>& pocket_drops() const { return drops_; }
  int ball_count() const { return static_cast<int>(segments_.size()); }
  /// The exact state of `ball` (file-order index) at time t (clamped to [0, duration]).
  BallState state(int ball, double t) const;
  std::vector<BallState> states(double t) const;
  /// The closed-form pieces of one ball's motion, in time order (for drawing paths).
  const std::vector<MotionSegment>& segments(int ball) const { return segments_[static_cast<std::size_t>(ball)]; }
  const PhysicsParams& physics() const { return physics_; }

 private:
  /// The state `seg` gives at time t (t at or after its start).
  BallState segment_state(const MotionSegment& seg, double t) const;

  PhysicsParams physics_;
  std::vector<Vec3> pocket_centres_;
  std::vector<double> pocket_radii_;
  std::vector<std::vector<MotionSegment>> segments_;
  std::vector<Event> events_;
  std::vector<PocketDrop> drops_;
};

/// s from the start event to the cue strike: room for the stick's approach and two practice strokes.
inline constexpr double kCueLeadTime = 2.5;

/// Runs the shot: start event, the cue strike at kCueLeadTime, every collision, the end event.
Timeline simulate(const Scene& scene);

}  // namespace bsim
