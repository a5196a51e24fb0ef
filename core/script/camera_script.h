#pragma once
// The scripted camera: the seed's hover / look / follow descriptions, interpolated around each
// listed event (Bezier look point, slerped direction, Smooth-eased distance).
#include <optional>
#include <vector>

#include "ball_track.h"
#include "camera_view.h"
#include "diagnostics.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

/// The time one listed description holds (from its event to the next listed event; the first one
/// also holds from the start of the shot to its event).
struct CameraSegment {
  int shot = 0;      ///< index into CameraScript::shots() (= Scene::camera when the scene lists any)
  double begin = 0;  ///< s
  double end = 0;    ///< s
};

/// An interpolation window around a listed event, from the description before it (shot - 1) to the
/// one that starts at it (shot). begin == end is a cut. The first listed event has none.
struct CameraWindow {
  int shot = 0;           ///< index into CameraScript::shots() of the description that starts at the event
  double begin = 0;       ///< s
  double event_time = 0;  ///< s
  double end = 0;         ///< s
};

class CameraScript {
 public:
  /// Checks the script against the simulated events (event numbers, order, ball indices) and
  /// resolves it. Returns nullopt and appends located errors when it does not fit the shot.
  /// A scene that lists no description gets default_shot(). `scene` and `timeline` must outlive
  /// the script.
  static std::optional<CameraScript> build(const Scene& scene, const Timeline& timeline,
                                           std::vector<Diagnostic>& diagnostics);
  /// The same for `shots` (copied) in place of the scene's own descriptions, the rest of the scene (its
  /// balls, its cue) read as it is: a script can be tried without a copy of the scene.
  static std::optional<CameraScript> build(const Scene& scene, const std::vector<CameraShot>& shots,
                                           const Timeline& timeline, std::vector<Diagnostic>& diagnostics);

  /// The camera used when a scene lists none: a wide hover over the middle of the table.
  static CameraShot default_shot(const Scene& scene);

  CameraPose pose(double t) const;
  /// Where one description alone would put the camera at t, without interpolation.
  CameraPose shot_pose(int shot, double t) const;
  const std::vector<CameraShot>& shots() const { return shots_; }
  const std::vector<CameraSegment>& segments() const { return segments_; }
  /// The description that holds at t (index into shots()): the one whose segment t is in, the first
  /// one before its event; -1 for a script with none.
  int shot_at(double t) const;
  const std::vector<CameraWindow>& windows() const { return windows_; }

 private:
  CameraPose interpolate(const CameraWindow& window, double t) const;

  const Timeline* timeline_ = nullptr;
  std::vector<CameraShot> shots_;
  std::vector<CameraSegment> segments_;
  std::vector<CameraWindow> windows_;
  std::vector<std::optional<BallTrack>> tracks_;  ///< per ball, for the balls the script watches
};

/// rad, the heading a `look` or `follow` camera's track of `ball` (ball_track.h) starts from: the
/// stick's, when a stick first sets the ball going (the cue of the shot in play then); none when a
/// ball sets it going first (the track then takes the direction of its first motion).
std::optional<double> struck_heading(const Scene& scene, const Timeline& timeline, int ball);

/// The later strikes of `ball` by a stick (after the event that first sets it going), each from its
/// shot's start: from there the track heads along that shot's stick.
std::vector<TrackStrike> later_strikes(const Scene& scene, const Timeline& timeline, int ball);

}  // namespace bsim
