#pragma once
// The scripted camera: the seed's hover / look / follow descriptions, interpolated around each
// listed event (Bezier look point, slerped direction, Smooth-eased distance).
#include <optional>
#include <vector>

#include "diagnostics.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

struct CameraPose {
  Vec3 location{0, 0, 0};  ///< m
  Vec3 look_at{0, 0, 0};   ///< m, the point at the centre of the view
  bool interpolating = false;
};

/// The time one listed description holds (from its event to the next listed event).
struct CameraSegment {
  int shot = 0;        ///< index into Scene::camera
  double begin = 0;    ///< s
  double end = 0;      ///< s
};

/// An interpolation window around a listed event.
struct CameraWindow {
  int shot = 0;          ///< index into Scene::camera of the description that starts at the event
  double begin = 0;      ///< s
  double event_time = 0; ///< s
  double end = 0;        ///< s
};

class CameraScript {
 public:
  /// Checks the script against the simulated events (event numbers, order, ball indices) and
  /// resolves it. Returns nullopt and appends located errors when it does not fit the shot.
  /// `scene` and `timeline` must outlive the script.
  static std::optional<CameraScript> build(const Scene& scene, const Timeline& timeline,
                                           std::vector<Diagnostic>& diagnostics);

  CameraPose pose(double t) const;
  const std::vector<CameraSegment>& segments() const { return segments_; }
  const std::vector<CameraWindow>& windows() const { return windows_; }

 private:
  const Scene* scene_ = nullptr;
  const Timeline* timeline_ = nullptr;
  std::vector<CameraSegment> segments_;
  std::vector<CameraWindow> windows_;
};

}  // namespace bsim
