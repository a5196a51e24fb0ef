#pragma once
// The replay: after the shot that wins a game, that shot again at half speed from the director's
// second camera, as television shows the winning ball again. This module chooses what is replayed
// (from a little before the stick's last stroke until the winning ball has dropped) and the second
// camera: a place the movie did not film from, clear of the table, the balls, the floor and the lamp
// (camera_clearance.h), written as the same camera descriptions a scene's script is made of.
#include <string>
#include <vector>

#include "camera_script.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

/// The replay's speed: simulation seconds per second of movie (half speed).
inline constexpr double kReplayRate = 0.5;
/// s of simulation before the winning shot's strike the replay starts from: the stick's back-swing
/// and its forward stroke.
inline constexpr double kReplayLead = 1.0;
/// s of simulation the replay runs on after the winning ball drops (it ends sooner when the balls
/// rest sooner, and never past the end of the simulation).
inline constexpr double kReplayTail = 0.5;
/// The least angle, degrees, between the replay camera's view and the movie's (seen from above) at
/// the moment that matters: the replay shows the shot from somewhere else.
inline constexpr double kReplayAngleDeg = 35.0;

/// What is replayed: the shot that won and the ball that matters in it.
struct ReplaySubject {
  int shot = 0;   ///< the winning shot (Timeline::shots(), from 0)
  int ball = -1;  ///< file-order index of the ball that won the game (the 9 or the 8); -1: none (a game won on a foul)
};

struct ReplayPlan {
  /// s of simulation replayed: from a little before the strike to a little after the winning ball
  /// drops; end - start is a whole number of seconds of movie at kReplayRate.
  double start = 0, end = 0;
  /// The second camera's descriptions (keyed to the shot's events; a script over the whole timeline
  /// of which only [start, end] is seen).
  std::vector<CameraShot> camera;
  std::string what;  ///< what the camera is, in words: "a camera low behind the top-right corner"
};

/// The replayed span of `subject`'s shot (see ReplayPlan::start).
ReplayPlan replay_span(const Timeline& timeline, const ReplaySubject& subject);

/// The replay of `subject`: its span and the second camera. The first candidate that is clear over
/// the whole timeline (no clearance warning), looks from at least kReplayAngleDeg away from `main`'s
/// view, and in which the stick at the ball covers no more than kDirectorStickShare of the picture
/// wins: a camera low behind the pocket the winning ball drops into, looking back along its way (the
/// strike in the distance, then the ball coming on and dropping), then the same higher or turned,
/// then a camera across the line of the shot; the default wide camera when none is. Deterministic.
/// (The stick comes and goes out of the replay's view as well: load_shot plans it against both
/// cameras, CueScript's AlsoFilmed.)
ReplayPlan plan_replay(const Scene& scene, const Timeline& timeline, const CameraScript& main,
                       const ReplaySubject& subject);

}  // namespace bsim
