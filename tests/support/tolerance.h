#pragma once
// Absolute tolerances for CHECKs: CHECK(x == test::near(expected, 1e-12)) passes when
// |x - expected| <= 1e-12 and, when it fails, prints the value, the expected value and the tolerance.
// (doctest::Approx is relative, with a floor of its epsilon: right for "the same number up to
// round-off", loose for a small expected value such as an angle of a few hundredths of a radian.)
#include <cmath>
#include <ostream>

#include "vec.h"

namespace bsim::test {

struct Near {
  double expected = 0;
  double tolerance = 0;
};

struct NearVec {
  Vec3 expected{0, 0, 0};
  double tolerance = 0;  ///< on the distance
};

/// A value within `tolerance` of `expected`.
inline Near near(double expected, double tolerance) { return {expected, tolerance}; }
/// A point within `tolerance` (distance) of `expected`.
inline NearVec near(const Vec3& expected, double tolerance) { return {expected, tolerance}; }

inline bool operator==(double actual, const Near& n) { return std::abs(actual - n.expected) <= n.tolerance; }
inline bool operator==(const Vec3& actual, const NearVec& n) { return (actual - n.expected).norm() <= n.tolerance; }

inline std::ostream& operator<<(std::ostream& out, const Near& n) {
  const auto precision = out.precision(17);
  out << n.expected << " +- " << n.tolerance;
  out.precision(precision);
  return out;
}

inline std::ostream& operator<<(std::ostream& out, const NearVec& n) {
  const auto precision = out.precision(17);
  out << "(" << n.expected.x() << ", " << n.expected.y() << ", " << n.expected.z() << ") +- " << n.tolerance;
  out.precision(precision);
  return out;
}

}  // namespace bsim::test
