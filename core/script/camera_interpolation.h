#pragma once
// The seed's camera interpolation pieces (Cinematography: Smooth, the quadratic Bezier look point,
// the slerped direction).
#include "vec.h"

namespace bsim {

/// The seed's C1 ease: 2u^2 below one half, 1 - 2(u-1)^2 above; 0 at 0, 1 at 1, flat at both ends.
double smooth(double u);

/// Quadratic Bezier with control points p0 (u = 0), p_mid and p1 (u = 1).
Vec3 bezier(const Vec3& p0, const Vec3& p_mid, const Vec3& p1, double u);

/// Great-circle interpolation between unit vectors. Parallel inputs give `a`; antiparallel ones turn
/// about a horizontal-preferring perpendicular axis, so a straight-down camera never gives NaN.
Vec3 slerp_unit(const Vec3& a, const Vec3& b, double u);

/// (to - from) normalised, or `fallback` when the two points (nearly) coincide.
Vec3 unit_or(const Vec3& from, const Vec3& to, const Vec3& fallback);

}  // namespace bsim
