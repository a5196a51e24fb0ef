// PLACEHOLDER until the physics lands.
#include "timeline.h"
#include "scene.h"
namespace bsim {
Timeline::Timeline(const Scene& scene, std::vector<std::vector<MotionSegment>> segments, std::vector<Event> events,
                   std::vector<PocketDrop> drops)
    : physics_(scene.physics), segments_(std::move(segments)), events_(std::move(events)), drops_(std::move(drops)) {}
double Timeline::cue_time() const { return 0; }
BallState Timeline::state(int ball, double) const { return segments_[static_cast<std::size_t>(ball)].front().start; }
std::vector<BallState> Timeline::states(double t) const {
  std::vector<BallState> out;
  for (int i = 0; i < ball_count(); ++i) out.push_back(state(i, t));
  return out;
}
Timeline simulate(const Scene& scene) { return Timeline(scene, {}, {}, {}); }
}  // namespace bsim
