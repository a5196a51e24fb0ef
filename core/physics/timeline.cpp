#include "timeline.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "motion.h"
#include "pocket_fall.h"
#include "scene.h"

namespace bsim {

/// What makes a query of one segment cheap: the orientations at the whole steps of its integration,
/// or its pocket fall saved every few steps.
struct Timeline::SegmentSteps {
  std::vector<Quat> orientations;
  std::unique_ptr<const FallPath> fall;
};

Timeline::Timeline(const Scene& scene, std::vector<std::vector<MotionSegment>> segments, std::vector<Event> events,
                   std::vector<PocketDrop> drops, std::vector<ShotSpan> shots)
    : physics_(scene.physics),
      segments_(std::move(segments)),
      events_(std::move(events)),
      drops_(std::move(drops)),
      shots_(std::move(shots)) {
  if (shots_.empty() && !events_.empty()) {
    ShotSpan only;
    only.rest = events_.back().time;
    for (const Event& e : events_)
      if (e.type == EventType::cue) {
        only.cue = e.time;
        break;
      }
    shots_.push_back(only);
  }
  find_settled();
  for (const Pocket& pocket : scene.pockets) {
    pocket_centres_.push_back(pocket.center);
    pocket_radii_.push_back(pocket.radius);
  }
  // Orientation only shows, so the physics leaves it out; carry it through each ball's segments here,
  // saving each segment's integration steps on the way, up to where the next segment (or the shot) ends.
  auto steps = std::make_shared<std::vector<std::vector<SegmentSteps>>>(segments_.size());
  for (std::size_t b = 0; b < segments_.size(); ++b) {
    auto& list = segments_[b];
    auto& saved = (*steps)[b];
    saved.resize(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
      const MotionSegment& seg = list[k];
      const double end = k + 1 < list.size() ? list[k + 1].t0 : duration();
      const double dt = std::max(0.0, end - seg.t0);
      if (seg.start.motion == Motion::falling && seg.pocket >= 0) {
        const auto p = static_cast<std::size_t>(seg.pocket);
        saved[k].fall =
            std::make_unique<const FallPath>(seg.start, Pocket{pocket_centres_[p], pocket_radii_[p], {}}, physics_, dt);
      } else {
        saved[k].orientations =
            orientation_steps(seg.start, physics_, std::min(dt, transition_time(seg.start, physics_)));
      }
      if (k + 1 < list.size()) list[k + 1].start.orientation = segment_state(seg, &saved[k], end, true).orientation;
    }
  }
  steps_ = std::move(steps);
  for (Event& e : events_)
    for (std::size_t k = 0; k < e.balls.size(); ++k) {
      const Quat q = state(e.balls[k], e.time).orientation;
      if (k < e.before.size()) e.before[k].orientation = q;
      if (k < e.after.size()) e.after[k].orientation = q;
    }
}

int Timeline::shot_at(double t) const {
  int k = 0;
  for (int i = 1; i < shot_count(); ++i)
    if (shots_[static_cast<std::size_t>(i)].start <= t) k = i;
  return k;
}

double Timeline::settled(int shot) const {
  BSIM_EXPECT(shot >= 0 && shot < shot_count(), "no such shot in the timeline");
  return settled_[static_cast<std::size_t>(shot)];
}

void Timeline::find_settled() {
  settled_.clear();
  for (const ShotSpan& span : shots_) {
    double last = span.cue;
    for (const std::vector<MotionSegment>& segs : segments_)
      for (std::size_t i = 0; i < segs.size(); ++i) {
        const Motion m = segs[i].start.motion;
        if (m != Motion::sliding && m != Motion::rolling && m != Motion::falling) continue;
        const double end = i + 1 < segs.size() ? segs[i + 1].t0 : duration();
        if (segs[i].t0 < span.rest && end > span.cue) last = std::max(last, std::min(end, span.rest));
      }
    settled_.push_back(last);
  }
}

BallState Timeline::segment_state(const MotionSegment& seg, const SegmentSteps* steps, double t,
                                  bool orientation) const {
  static const std::vector<Quat> kNone;
  const double dt = std::max(0.0, t - seg.t0);
  if (seg.start.motion == Motion::falling && seg.pocket >= 0) {
    BallState s;
    if (steps && steps->fall) {
      s = steps->fall->state(dt);
    } else {
      const auto p = static_cast<std::size_t>(seg.pocket);
      const Pocket pocket{pocket_centres_[p], pocket_radii_[p], {}};
      s = fall_state(seg.start, pocket, physics_, dt);
    }
    if (orientation) s.orientation = advance_orientation(seg.start, physics_, dt);
    return s;
  }
  // A state's formulas hold up to its transition; a later time belongs to the next segment.
  const double valid = std::min(dt, transition_time(seg.start, physics_));
  BallState s = evolve(seg.start, physics_, valid);
  if (orientation) s.orientation = advance_orientation(seg.start, physics_, valid, steps ? steps->orientations : kNone);
  return s;
}

std::size_t Timeline::segment_at(int ball, double& t) const {
  BSIM_EXPECT(ball >= 0 && ball < ball_count(), "no such ball in the timeline");
  const auto& list = segments_[static_cast<std::size_t>(ball)];
  BSIM_EXPECT(!list.empty(), "a ball of the timeline has no motion segment");
  BSIM_EXPECT(!std::isnan(t), "a motion segment looked up at a time that is not a number");
  t = std::clamp(t, 0.0, duration());
  auto it = std::upper_bound(list.begin(), list.end(), t, [](double v, const MotionSegment& s) { return v < s.t0; });
  if (it != list.begin()) --it;
  return static_cast<std::size_t>(it - list.begin());
}

BallState Timeline::state(int ball, double t) const {
  const std::size_t k = segment_at(ball, t);
  const auto b = static_cast<std::size_t>(ball);
  return segment_state(segments_[b][k], steps_ ? &(*steps_)[b][k] : nullptr, t, true);
}

BallState Timeline::motion_state(int ball, double t) const {
  const std::size_t k = segment_at(ball, t);
  const auto b = static_cast<std::size_t>(ball);
  return segment_state(segments_[b][k], steps_ ? &(*steps_)[b][k] : nullptr, t, false);
}

std::vector<BallState> Timeline::states(double t) const {
  std::vector<BallState> out;
  out.reserve(segments_.size());
  for (int i = 0; i < ball_count(); ++i) out.push_back(state(i, t));
  return out;
}

}  // namespace bsim
