#pragma once
// Doctest printing for the physics value types, so a failing CHECK shows the state, not an address.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "ball_state.h"

namespace bsim::test {

inline std::string describe(const Vec3& v) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

inline std::string describe(const BallState& s) {
  return std::string(to_string(s.motion)) + " at " + describe(s.position) + " v " + describe(s.velocity) + " w " +
         describe(s.spin);
}

}  // namespace bsim::test

namespace doctest {
template <>
struct StringMaker<bsim::BallState> {
  static String convert(const bsim::BallState& s) { return bsim::test::describe(s).c_str(); }
};
template <>
struct StringMaker<bsim::Vec3> {
  static String convert(const bsim::Vec3& v) { return bsim::test::describe(v).c_str(); }
};
}  // namespace doctest
