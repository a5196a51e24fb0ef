#include "lens.h"

#include <algorithm>
#include <cmath>

#include "camera_view.h"

namespace bsim {

namespace {

/// Instants the focus puller's bell is sampled at (the midpoints of as many equal steps).
constexpr int kFocusSamples = 24;

/// The bell, u (1 - u)^2 over u in [0, 1]: a Beta(2, 3) density, nothing at either end, its weight
/// mostly in the first half, so the focus responds after a moment and settles smoothly.
double bell(double u) { return u * (1 - u) * (1 - u); }

/// The latest cut of the script at or before t (a window of no length), or -infinity.
double latest_cut(const CameraScript& script, double t) {
  double cut = -INFINITY;
  for (const CameraWindow& w : script.windows())
    if (w.begin == w.end && w.event_time <= t) cut = std::max(cut, w.event_time);
  return cut;
}

}  // namespace

double focal_length_mm(double hfov_deg) { return 0.5 * kSensorWidthMm / std::tan(0.5 * hfov_deg * kDegToRad); }

double aperture_for(double focus) {
  const double ratio = focus / kOpenFocus;
  return std::clamp(kOpenAperture * ratio * ratio, kOpenAperture, kClosedAperture);
}

double circle_of_confusion_px(const Lens& lens, double distance, double width) {
  const double f = lens.focal_mm * 1e-3, s = distance, sf = lens.focus;
  const double c = f * f * (s - sf) / (lens.aperture * s * (sf - f));  // m on the sensor
  return c * 1e3 * width / kSensorWidthMm;
}

double focus_target(const CameraPose& pose) { return std::max(kNearestFocus, (pose.look_at - pose.location).norm()); }

double eased_focus(const CameraScript& script, double t, double since, double rate) {
  const double earliest = std::max(since, latest_cut(script, t));
  const double span = kFocusPull * rate;
  double sum = 0, weight = 0;
  for (int j = 0; j < kFocusSamples; ++j) {
    const double u = (j + 0.5) / kFocusSamples;
    const double w = bell(u);
    sum += w * focus_target(script.pose(std::max(earliest, t - u * span)));
    weight += w;
  }
  return sum / weight;
}

Lens frame_lens(const CameraScript& script, double t, double since, double rate) {
  Lens lens;
  lens.focal_mm = focal_length_mm(kCameraFovDeg);
  lens.focus = eased_focus(script, t, since, rate);
  lens.aperture = aperture_for(lens.focus);
  return lens;
}

}  // namespace bsim
