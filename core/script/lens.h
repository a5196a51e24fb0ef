#pragma once
// The lens the movie is filmed through: a 36 mm-wide (full-frame) sensor behind a lens whose focal
// length gives the scene camera's field of view, focused where the camera script looks, as a focus
// puller keeps a subject sharp (a little behind a change, never jumping but at a cut), at an
// aperture that keeps a wide shot sharp from the near rail to the far wall, as a broadcast camera's
// picture is, and opens for a close one, so a ball under a metre from the lens stands sharp in front
// of a soft table. The develop stage blurs each frame by the circle of confusion this lens gives each
// point (export/develop.h).
#include "camera_script.h"

namespace bsim {

/// mm, the sensor's width: a full-frame (35 mm film) camera's.
inline constexpr double kSensorWidthMm = 36.0;

/// s of movie time the focus puller takes to follow a change of the distance to the subject (the
/// focus comes 95 % of the way in about 0.35 s, half of it in 0.17 s).
inline constexpr double kFocusPull = 0.45;
/// m, the nearest the lens focuses (a 35 mm lens's close-focus distance).
inline constexpr double kNearestFocus = 0.3;

/// The aperture: f/2.8 wide open for a subject at kOpenFocus or nearer, closing with the square of
/// the distance beyond (f/5.6 at 1.41 m, f/11 at 1.98 m) to f/16 (kClosedAperture) from 2.39 m on.
inline constexpr double kOpenAperture = 2.8;
inline constexpr double kClosedAperture = 16.0;
inline constexpr double kOpenFocus = 1.0;  ///< m

/// What the lens does in one frame.
struct Lens {
  double focal_mm = 0;  ///< the focal length
  double aperture = 0;  ///< the f-number N
  double focus = 0;     ///< m, the distance it is focused at, along its axis
};

/// mm, the focal length that gives a horizontal field of view of `hfov_deg` on the sensor:
/// 18 / tan(hfov / 2), 34.64 mm for the scene camera's 55 degrees.
double focal_length_mm(double hfov_deg);

/// The aperture for a lens focused at `focus` m (see kOpenAperture).
double aperture_for(double focus);

/// Pixels, the diameter of the circle of confusion of a point `distance` m in front of the lens (along
/// its axis) in a picture `width` pixels wide (the sensor's width): the thin-lens formula
/// c = f^2 |S - Sf| / (N S (Sf - f)) on the sensor (Potmesil & Chakravarty 1981, "A lens and aperture
/// camera model for synthetic image generation", SIGGRAPH; as restated by Schedl & Wimmer, GPU Pro 4),
/// times width / kSensorWidthMm. Positive behind the focus, negative in front of it.
double circle_of_confusion_px(const Lens& lens, double distance, double width);

/// m, the distance the focus puller aims at for a camera pose: from the camera to the point it looks
/// at (at least kNearestFocus).
double focus_target(const CameraPose& pose);

/// m, where the focus is at simulation time t of `script`: the target distance (focus_target) over the
/// last kFocusPull s of movie time, weighted by a smooth bell that starts and ends at nothing, so the
/// focus follows a change after a moment and eases into it. `rate` is simulation seconds per movie
/// second (0.5 in a half-speed replay). History goes back no further than `since` (the start of the
/// movie's stretch this frame belongs to) nor past the script's latest cut at or before t: a cut
/// starts on a new take, focused on its subject from its first frame, as an editor cuts between takes
/// and never on a pull.
double eased_focus(const CameraScript& script, double t, double since, double rate);

/// The lens of the frame at simulation time t of `script` (eased_focus) for a picture of the scene
/// camera's field of view.
Lens frame_lens(const CameraScript& script, double t, double since, double rate);

}  // namespace bsim
