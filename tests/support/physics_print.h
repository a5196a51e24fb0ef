#pragma once
// Doctest printing for the physics value types, so a failing CHECK(a == b) shows the values, not
// "{?}": a ball's state, a contact, an event, a motion segment, a pocket drop, and a timeline in brief.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "ball_state.h"
#include "event.h"
#include "timeline.h"

namespace bsim::test {

inline std::string describe(const Vec3& v) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

inline std::string describe(const Quat& q) {
  std::ostringstream out;
  out.precision(17);
  out << "(w " << q.w() << ", " << q.x() << ", " << q.y() << ", " << q.z() << ")";
  return out.str();
}

inline std::string describe(const BallState& s) {
  return std::string(to_string(s.motion)) + " at " + describe(s.position) + " v " + describe(s.velocity) + " w " +
         describe(s.spin) + " q " + describe(s.orientation);
}

inline std::string describe(const Contact& c) {
  std::ostringstream out;
  out.precision(17);
  out << "contact " << c.a << "-" << c.b << " at t " << c.time << " speed " << c.speed << " where "
      << describe(c.where);
  return out.str();
}

inline std::string describe(const Event& e) {
  std::ostringstream out;
  out.precision(17);
  out << "event " << e.index << " " << to_string(e.type) << " at t " << e.time << " balls [";
  for (std::size_t k = 0; k < e.balls.size(); ++k) out << (k ? " " : "") << e.balls[k];
  out << "] rail " << e.rail << " speed " << e.speed << " where " << describe(e.where);
  for (std::size_t k = 0; k < e.before.size(); ++k) out << "\n  before: " << describe(e.before[k]);
  for (std::size_t k = 0; k < e.after.size(); ++k) out << "\n  after: " << describe(e.after[k]);
  for (const Contact& c : e.contacts) out << "\n  " << describe(c);
  return out.str();
}

inline std::string describe(const MotionSegment& s) {
  std::ostringstream out;
  out.precision(17);
  out << "segment from t " << s.t0 << " pocket " << s.pocket << ": " << describe(s.start);
  return out.str();
}

inline std::string describe(const PocketDrop& d) {
  std::ostringstream out;
  out.precision(17);
  out << "ball " << d.ball << " drops into pocket " << d.pocket << " at t " << d.time;
  return out.str();
}

/// A timeline in brief: the values that tell two apart at a glance (compare the parts to see more).
inline std::string describe(const Timeline& t) {
  std::ostringstream out;
  out.precision(17);
  std::size_t segments = 0;
  for (int b = 0; b < t.ball_count(); ++b) segments += t.segments(b).size();
  out << "timeline of " << t.ball_count() << " balls, " << t.duration() << " s, " << t.events().size() << " events, "
      << segments << " segments, " << t.pocket_drops().size() << " pocket drops";
  return out.str();
}

}  // namespace bsim::test

namespace doctest {
#define BSIM_DOCTEST_PRINT(Type)                                                             \
  template <>                                                                                \
  struct StringMaker<Type> {                                                                 \
    static String convert(const Type& value) { return bsim::test::describe(value).c_str(); } \
  };
BSIM_DOCTEST_PRINT(bsim::Vec3)
BSIM_DOCTEST_PRINT(bsim::BallState)
BSIM_DOCTEST_PRINT(bsim::Contact)
BSIM_DOCTEST_PRINT(bsim::Event)
BSIM_DOCTEST_PRINT(bsim::MotionSegment)
BSIM_DOCTEST_PRINT(bsim::PocketDrop)
BSIM_DOCTEST_PRINT(bsim::Timeline)
#undef BSIM_DOCTEST_PRINT
}  // namespace doctest
