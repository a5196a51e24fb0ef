#pragma once
// The kinematic state of one ball at one instant.
#include <string>
#include <string_view>

#include "vec.h"

namespace bsim {

enum class Motion { stationary, sliding, rolling, spinning, falling, pocketed };

/// The name used in trajectory.csv: "stationary", "sliding", ...
std::string_view to_string(Motion motion);

struct BallState {
  Vec3 position{0, 0, 0};  ///< m, centre
  Vec3 velocity{0, 0, 0};  ///< m/s
  Vec3 spin{0, 0, 0};      ///< rad/s, angular velocity
  Quat orientation = Quat::Identity();
  Motion motion = Motion::stationary;

  /// Every field the same (the orientation by its four coefficients, as Eigen's quaternion has no ==).
  bool operator==(const BallState& o) const {
    return position == o.position && velocity == o.velocity && spin == o.spin &&
           orientation.coeffs() == o.orientation.coeffs() && motion == o.motion;
  }
};

/// Whether a ball in this state is on the bed (not falling into a pocket nor in one).
inline bool on_bed(const BallState& s) { return s.motion != Motion::falling && s.motion != Motion::pocketed; }

/// "(x, y)" of a point on the bed to the millimetre, for messages.
std::string plan_text(const Vec3& p);

}  // namespace bsim
