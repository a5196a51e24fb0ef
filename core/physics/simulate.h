#pragma once
// The event loop: the only place that sequences motion (motion.h), detection (detect.h) and
// resolution (resolve.h, pocket_fall.h). simulate() in timeline.h wraps it into a Timeline.
#include <vector>

#include "event.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

/// s the end event waits, at least, after the last ball comes to rest or settles in a pocket.
inline constexpr double kEndHold = 0.5;
/// s; the shot's duration is rounded up to a whole number of these, so that every integer frame rate
/// gives a whole number of frames and the movie and sound track lengths agree exactly.
inline constexpr double kDurationStep = 1.0;
/// s after the cue strike at which a shot that never comes to rest (say, mu_roll = 0) is cut off.
inline constexpr double kMaxShotTime = 600.0;

/// Events and transitions after which a shot is cut off (a safety net against a runaway simulation).
inline constexpr long kMaxSteps = 2'000'000;

/// m/s, closing speed below which a contact that would at once press again (a push) does not bounce.
inline constexpr double kPushSpeed = 0.01;

/// m/s, least closing speed of a numbered ball-ball or ball-rail event. Gentler contacts (balls resting
/// against each other being pushed, a ball pressed against a cushion) are resolved but not numbered:
/// nothing worth a sound or a camera cut happens below a centimetre a second.
inline constexpr double kMinEventSpeed = 0.01;

struct SimulationResult {
  std::vector<std::vector<MotionSegment>> segments;  ///< per ball, in time order; orientations not yet set
  std::vector<Event> events;                         ///< numbered, start to end
  std::vector<PocketDrop> drops;
  long candidates_tested = 0;  ///< contact tests run (for the bench)
  long groups = 0;             ///< group collisions resolved (group.h)
  long group_steps = 0;        ///< their integration steps in all (for the bench)
  bool cut_off = false;        ///< the shot reached kMaxShotTime (or kMaxSteps) still moving
  double rest = 0;             ///< s, from when every ball is at rest (or where a cut-off shot stops)
};

/// Runs one shot's physics: the scene's first cue struck at kCueLeadTime, then events and closed-form
/// motion segments, without orientations. Balls with Ball::pocket set lie in their pockets throughout.
/// play.h strings shots together.
SimulationResult simulate_events(const Scene& scene);

/// s, the end event's time for a scene whose balls rest from `rest`: kEndHold later, rounded up to a
/// whole kDurationStep.
double shot_end(double rest);

}  // namespace bsim
