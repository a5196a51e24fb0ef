#pragma once
// The seed's camera interpolation pieces (Cinematography: Smooth, the quadratic Bezier look point,
// the slerped direction) and the view test the cue stick uses to leave the picture unseen.
#include "vec.h"

namespace bsim {

/// Horizontal field of view of the scene camera in degrees, the same for POV-Ray and the GL preview.
inline constexpr double kCameraFovDeg = 55.0;

/// The seed's C1 ease: 2u^2 below one half, 1 - 2(u-1)^2 above; 0 at 0, 1 at 1, flat at both ends.
double smooth(double u);

/// Quadratic Bezier with control points p0 (u = 0), p_mid and p1 (u = 1).
Vec3 bezier(const Vec3& p0, const Vec3& p_mid, const Vec3& p1, double u);

/// Great-circle interpolation between unit vectors. Parallel inputs give `a`; antiparallel ones turn
/// about a horizontal-preferring perpendicular axis, so a straight-down camera never gives NaN.
Vec3 slerp_unit(const Vec3& a, const Vec3& b, double u);

/// (to - from) normalised, or `fallback` when the two points (nearly) coincide.
Vec3 unit_or(const Vec3& from, const Vec3& to, const Vec3& fallback);

/// Half-angle, degrees, of a cone around the view direction that contains the whole picture for any
/// aspect from square to wide (the horizontal field of view is kCameraFovDeg).
double view_cone_half_angle_deg();

/// Whether `point` can appear in the picture of a camera at `location` looking at `look_at`.
bool in_view(const Vec3& location, const Vec3& look_at, const Vec3& point);

}  // namespace bsim
