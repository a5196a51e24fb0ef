#pragma once
// A hash of every bit the physics gives for a shot (each motion segment, event and pocket drop, every
// double by its bytes): the same hash means the same events to the bit. The physics golden test holds
// it over seeded random breaks and tables; tests/bench/physics_ab.sh compares two builds with it.
// No test framework, so the benchmarks use it too.
#include <cstdint>
#include <cstring>

#include "simulate.h"

namespace bsim::test {

/// FNV-1a over the bytes of every value of simulation results, added one after the other.
class PhysicsFingerprint {
 public:
  void add(const SimulationResult& r) {
    for (const auto& list : r.segments)
      for (const MotionSegment& s : list) {
        value(s.t0);
        state(s.start);
        value(s.pocket);
      }
    for (const Event& e : r.events) event(e);
    for (const PocketDrop& d : r.drops) {
      value(d.time);
      value(d.ball);
      value(d.pocket);
    }
    value(r.cut_off);
    value(r.rest);
  }
  std::uint64_t hash() const { return hash_; }

 private:
  template <class T>
  void value(const T& v) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    for (unsigned char c : bytes) hash_ = (hash_ ^ c) * 0x100000001b3ull;
  }
  void vec(const Vec3& v) {
    for (int k = 0; k < 3; ++k) value(v[k]);
  }
  void state(const BallState& s) {
    vec(s.position);
    vec(s.velocity);
    vec(s.spin);
    for (int k = 0; k < 4; ++k) value(s.orientation.coeffs()[k]);
    value(s.motion);
  }
  void event(const Event& e) {
    value(e.index);
    value(e.time);
    value(e.type);
    for (int b : e.balls) value(b);
    value(e.rail);
    value(e.pocket);
    value(e.speed);
    vec(e.where);
    for (const BallState& s : e.before) state(s);
    for (const BallState& s : e.after) state(s);
    for (const Contact& c : e.contacts) {
      value(c.a);
      value(c.b);
      value(c.time);
      value(c.speed);
      vec(c.where);
    }
    value(e.grouped);
  }
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace bsim::test
