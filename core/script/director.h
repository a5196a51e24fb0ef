#pragma once
// The automatic director: a camera script written from the simulated shot, the way broadcast pool
// is shot, as the same descriptions the parser makes (so it runs through CameraScript, the
// clearance checks, camera.csv and every picture unchanged) and as scene text to paste and edit.
#include <string>
#include <vector>

#include "camera_script.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

/// m/s the camera's location may move at most: one operator carrying it round the table. The
/// fastest walk of adults in their twenties is about 2.5 m/s (Bohannon, "Comfortable and maximum
/// walking speed of adults aged 20-79 years", Age and Ageing 26, 1997: 2.53 m/s for men, 2.47 m/s
/// for women); a Steadicam operator walks, so that is the bound. The director plans below 85 % of it.
inline constexpr double kCameraCarrySpeed = 2.5;
/// m the director keeps its camera from every ball's surface (so from the centre: radius + this),
/// more than the clearance warnings' room for the lens (kCameraBallClearance).
inline constexpr double kDirectorBallRoom = 0.15;
/// The most of the picture the stick may cover (stick_picture_share) while it is at the cue ball, from
/// its address to its follow-through. A shooter's view down a level stick shows it in under 1 %; a
/// camera low on the line of a stick raised over a cushion looks along it, its butt filling an eighth
/// of the picture or more.
inline constexpr double kDirectorStickShare = 0.05;
/// s, the shortest span of a description (its key to the next one's, or to the end).
inline constexpr double kMinDescriptionSeconds = 1.0;

/// The line the action runs along at a description's key (horizontal): the 180-degree rule keeps
/// the camera on one side of it across the change to that description.
struct LineOfAction {
  Vec3 point{0, 0, 0};      ///< m
  Vec3 direction{1, 0, 0};  ///< unit, horizontal
  /// m, the signed distance of `p` from the line seen from above: > 0 on its left.
  double side(const Vec3& p) const;
};

struct DirectedCamera {
  std::vector<CameraShot> shots;      ///< as the parser would make them from text() (no source locations)
  std::vector<std::string> comments;  ///< one line per description: what it shows
  std::vector<LineOfAction> lines;    ///< per description: the line of action at its key
  std::vector<int> subjects;          ///< per description: the ball it is about
};

/// s, how long a game's opening wide shot holds before the cut to the breaker's view (the rest of the
/// break's approach, kCueLeadTime less this, stays the shooter's).
inline constexpr double kOpeningSeconds = 1.2;

/// What the director is told of a shot beyond its physics: a game's rules know what each shot was for.
struct FilmingNotes {
  /// Open on a wide shot of the whole table (the rack, the breaker's cue ball) before the first
  /// stroke, as a broadcast opens a rack.
  bool opening = false;
  /// Per shot (by index), the ball (file order) whose fate is the shot's point when the physics alone
  /// would pick another, or -1: a safety's point is where the cue ball hides, a foul's the ball it
  /// should have hit first.
  std::vector<int> subjects;
};

/// Writes the camera script for the simulated shot. Deterministic: the same scene, timeline and notes
/// give the same script, to the bit.
DirectedCamera direct_camera(const Scene& scene, const Timeline& timeline, const FilmingNotes& notes = {});

/// The script as scene text: "camera", one `event KEY PRE POST MODE ...  # comment` line per
/// description, "endcamera"; it parses back to `camera.shots` exactly.
std::string camera_script_text(const DirectedCamera& camera, const std::string& scene_name);

}  // namespace bsim
