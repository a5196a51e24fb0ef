#include "timeline.h"

#include <algorithm>

#include "motion.h"
#include "pocket_fall.h"
#include "scene.h"

namespace bsim {

Timeline::Timeline(const Scene& scene, std::vector<std::vector<MotionSegment>> segments, std::vector<Event> events,
                   std::vector<PocketDrop> drops)
    : physics_(scene.physics), segments_(std::move(segments)), events_(std::move(events)), drops_(std::move(drops)) {
  for (const Pocket& pocket : scene.pockets) {
    pocket_centres_.push_back(pocket.center);
    pocket_radii_.push_back(pocket.radius);
  }
  // Orientation only shows, so the physics leaves it out; carry it through each ball's segments here.
  for (auto& list : segments_)
    for (std::size_t k = 1; k < list.size(); ++k)
      list[k].start.orientation = segment_state(list[k - 1], list[k].t0).orientation;
  for (Event& e : events_)
    for (std::size_t k = 0; k < e.balls.size(); ++k) {
      const Quat q = state(e.balls[k], e.time).orientation;
      if (k < e.before.size()) e.before[k].orientation = q;
      if (k < e.after.size()) e.after[k].orientation = q;
    }
}

double Timeline::cue_time() const {
  for (const Event& e : events_)
    if (e.type == EventType::cue) return e.time;
  return 0;
}

BallState Timeline::segment_state(const MotionSegment& seg, double t) const {
  const double dt = std::max(0.0, t - seg.t0);
  if (seg.start.motion == Motion::falling && seg.pocket >= 0) {
    const auto p = static_cast<std::size_t>(seg.pocket);
    const Pocket pocket{pocket_centres_[p], pocket_radii_[p], {}};
    BallState s = fall_state(seg.start, pocket, physics_, dt);
    s.orientation = advance_orientation(seg.start, physics_, dt);
    return s;
  }
  // A state's formulas hold up to its transition; a later time belongs to the next segment.
  const double valid = std::min(dt, transition_time(seg.start, physics_));
  BallState s = evolve(seg.start, physics_, valid);
  s.orientation = advance_orientation(seg.start, physics_, valid);
  return s;
}

BallState Timeline::state(int ball, double t) const {
  const auto& list = segments_[static_cast<std::size_t>(ball)];
  t = std::clamp(t, 0.0, duration());
  auto it = std::upper_bound(list.begin(), list.end(), t, [](double v, const MotionSegment& s) { return v < s.t0; });
  if (it != list.begin()) --it;
  return segment_state(*it, t);
}

std::vector<BallState> Timeline::states(double t) const {
  std::vector<BallState> out;
  out.reserve(segments_.size());
  for (int i = 0; i < ball_count(); ++i) out.push_back(state(i, t));
  return out;
}

}  // namespace bsim
