#pragma once
// A shot's states worked out directly: each from its segment's start alone with evolve,
// advance_orientation and fall_state, nothing saved, each segment's starting orientation carried from
// the first segment. What the Timeline's saved steps must give to the bit (the tests), and the
// exporter's old way of answering a query (the export benchmark's baseline).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "motion.h"
#include "pocket_fall.h"
#include "scene.h"
#include "timeline.h"

namespace bsim::test {

class DirectStates {
 public:
  /// Keeps references to both: they must outlive it.
  DirectStates(const Scene& scene, const Timeline& timeline) : scene_(&scene), timeline_(&timeline) {
    for (int b = 0; b < timeline.ball_count(); ++b) {
      std::vector<MotionSegment> list = timeline.segments(b);
      for (std::size_t k = 1; k < list.size(); ++k)
        list[k].start.orientation = segment_state(list[k - 1], list[k].t0).orientation;
      segments_.push_back(std::move(list));
    }
  }

  /// The state `seg` gives at time t (at or after its start); without `orientation`, the orientation
  /// is left as at the segment's start (as Timeline::motion_state leaves it).
  BallState segment_state(const MotionSegment& seg, double t, bool orientation = true) const {
    const PhysicsParams& physics = timeline_->physics();
    const double dt = std::max(0.0, t - seg.t0);
    if (seg.start.motion == Motion::falling && seg.pocket >= 0) {
      BallState s = fall_state(seg.start, scene_->pockets[static_cast<std::size_t>(seg.pocket)], physics, dt);
      if (orientation) s.orientation = advance_orientation(seg.start, physics, dt);
      return s;
    }
    const double valid = std::min(dt, transition_time(seg.start, physics));
    BallState s = evolve(seg.start, physics, valid);
    if (orientation) s.orientation = advance_orientation(seg.start, physics, valid);
    return s;
  }

  /// `ball`'s segments, each start's orientation carried from the first segment.
  const std::vector<MotionSegment>& segments(int ball) const { return segments_[static_cast<std::size_t>(ball)]; }

  /// The segment of `ball` that holds t, with t clamped to the shot.
  const MotionSegment& segment_at(int ball, double& t) const {
    const std::vector<MotionSegment>& list = segments(ball);
    t = std::clamp(t, 0.0, timeline_->duration());
    std::size_t k = 0;
    while (k + 1 < list.size() && list[k + 1].t0 <= t) ++k;
    return list[k];
  }

  /// The state of `ball` at t (clamped to the shot), as Timeline::state gives it.
  BallState state(int ball, double t) const {
    const MotionSegment& seg = segment_at(ball, t);
    return segment_state(seg, t);
  }

  /// state() without the orientation.
  BallState motion_state(int ball, double t) const {
    const MotionSegment& seg = segment_at(ball, t);
    return segment_state(seg, t, false);
  }

  bool falling(int ball, double t) const { return segment_at(ball, t).start.motion == Motion::falling; }

 private:
  const Scene* scene_;
  const Timeline* timeline_;
  std::vector<std::vector<MotionSegment>> segments_;
};

}  // namespace bsim::test
