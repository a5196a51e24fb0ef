#pragma once
// The simulated shot: every ball's exact state at any time, and the numbered events.
// Everything downstream (camera, stick, sound, frames, preview) reads only this.
#include <memory>
#include <vector>

#include "check.h"
#include "event.h"
#include "physics_params.h"

namespace bsim {

struct Scene;

/// A stretch of one ball's motion in closed form: from `start` at `t0` until the next segment.
struct MotionSegment {
  double t0 = 0;    ///< s
  BallState start;  ///< state at t0
  int pocket = -1;  ///< falling/pocketed: the pocket it drops into
  bool operator==(const MotionSegment&) const = default;
};

class Timeline {
 public:
  Timeline() = default;
  /// `shots` in time order; none: one shot spanning the events (its cue the first cue event, its rest
  /// the end event's time).
  Timeline(const Scene& scene, std::vector<std::vector<MotionSegment>> segments, std::vector<Event> events,
           std::vector<PocketDrop> drops, std::vector<ShotSpan> shots = {});

  /// s, time of the end event.
  double duration() const { return events_.empty() ? 0.0 : events_.back().time; }
  /// s, time of the first shot's cue event.
  double cue_time() const { return shots_.empty() ? 0.0 : shots_.front().cue; }
  /// The shots in order (at least one once built from a simulation).
  const std::vector<ShotSpan>& shots() const { return shots_; }
  int shot_count() const { return static_cast<int>(shots_.size()); }
  /// The shot whose stretch holds t: the last one starting at or before it (0 before the first).
  int shot_at(double t) const;
  /// s, when shot `shot` is settled: its last ball stops moving over the cloth or in a pocket (from
  /// then until its rest, balls at most spin in place; the rules' verdict is known). Its strike when
  /// nothing moves after it.
  double settled(int shot) const;
  const std::vector<Event>& events() const { return events_; }
  const std::vector<PocketDrop>& pocket_drops() const { return drops_; }
  int ball_count() const { return static_cast<int>(segments_.size()); }
  /// The exact state of `ball` (file-order index) at time t (clamped to [0, duration]). Cheap at any
  /// t: the integrated parts (a turning spin axis, a pocket fall) resume from steps saved once.
  BallState state(int ball, double t) const;
  /// state() without the orientation (left as at the start of the segment), for callers that need
  /// only where the ball is and how it moves.
  BallState motion_state(int ball, double t) const;
  std::vector<BallState> states(double t) const;
  /// The closed-form pieces of one ball's motion, in time order (for drawing paths).
  const std::vector<MotionSegment>& segments(int ball) const {
    BSIM_EXPECT(ball >= 0 && ball < ball_count(), "no such ball in the timeline");
    return segments_[static_cast<std::size_t>(ball)];
  }
  const PhysicsParams& physics() const { return physics_; }
  /// The same shot: the same physics, pockets, segments, events and drops (the saved steps follow
  /// from them).
  bool operator==(const Timeline& o) const {
    return physics_ == o.physics_ && pocket_centres_ == o.pocket_centres_ && pocket_radii_ == o.pocket_radii_ &&
           segments_ == o.segments_ && events_ == o.events_ && drops_ == o.drops_ && shots_ == o.shots_;
  }

 private:
  struct SegmentSteps;
  /// The state `seg` gives at time t (t at or after its start), resumed from its saved steps if given.
  BallState segment_state(const MotionSegment& seg, const SegmentSteps* steps, double t, bool orientation) const;
  /// The segment of `ball` that holds t (clamped), with its index.
  std::size_t segment_at(int ball, double& t) const;

  PhysicsParams physics_;
  std::vector<Vec3> pocket_centres_;
  std::vector<double> pocket_radii_;
  std::vector<std::vector<MotionSegment>> segments_;
  std::vector<Event> events_;
  std::vector<PocketDrop> drops_;
  std::vector<ShotSpan> shots_;
  std::vector<double> settled_;  ///< per shot, settled(): found once from the segments
  /// Fills settled_ from the segments and shots.
  void find_settled();
  /// Per ball and segment, the integration steps saved at construction (shared by copies: it never
  /// changes once built).
  std::shared_ptr<const std::vector<std::vector<SegmentSteps>>> steps_;
};

/// s from the start event to the cue strike: room for the stick's approach and two practice strokes.
/// A later shot's stick comes in kCueLeadTime before its strike too.
inline constexpr double kCueLeadTime = 2.5;

/// Runs the scene's shots at their cues' headings as given (play.h aims them first): start event, the
/// first cue strike at kCueLeadTime, every collision, each later shot after the one before rests, the
/// end event.
Timeline simulate(const Scene& scene);

}  // namespace bsim
