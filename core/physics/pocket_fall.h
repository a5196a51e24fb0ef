#pragma once
// A ball dropping into a pocket, after the seed's model: its centre has crossed the pocket's circle.
// Below sqrt(g R) it rolls over the edge (pivoting on the lip until the lip's push vanishes, which
// happens at once from sqrt(g R) up: the seed's threshold), then it flies; it bounces off the pocket's
// far wall and stops at a fixed depth, where it stays, taking no further part in the shot.
// Only for display: integrated in fixed steps from the entry, so every query gives the same answer.
#include <vector>

#include "ball_state.h"
#include "physics_params.h"
#include "scene.h"

namespace bsim {

/// m, how far below its height on the bed a pocketed ball's centre comes to rest.
inline constexpr double kPocketDepth = 0.1;
/// Share of the normal speed a ball keeps bouncing off the pocket's wall.
inline constexpr double kPocketWallRestitution = 0.3;
/// s, integration step of the drop.
inline constexpr double kFallStep = 1.0 / 2000.0;

/// s from entering the pocket to resting at its bottom.
double fall_duration(const BallState& entry, const Pocket& pocket, const PhysicsParams& params);

/// The falling ball dt seconds after it entered (state `falling`; `pocketed` from fall_duration on).
BallState fall_state(const BallState& entry, const Pocket& pocket, const PhysicsParams& params, double dt);

/// A fall to its end: its duration, fall_duration, and fall_state at that duration, the same to the bit
/// as those two give, from one integration instead of two.
struct FallEnd {
  double duration = 0;  ///< s
  BallState state;
};
FallEnd fall_end(const BallState& entry, const Pocket& pocket, const PhysicsParams& params);

/// One fall's integration saved every few steps up to dt_max: fall_state at any dt then repeats at
/// most kSaveEvery steps from the last save before it, and gives the same state to the bit (the
/// steps it takes are the ones fall_state takes from the entry). Past dt_max it steps on from the end.
class FallPath {
 public:
  /// What one step of the fall changes.
  struct Saved {
    Vec3 position{0, 0, 0};
    Vec3 velocity{0, 0, 0};
    double theta = 0;
    double theta_rate = 0;
    double t = 0;
    bool pivoting = false;
    bool settled = false;
  };
  /// Steps between saves.
  static constexpr long kSaveEvery = 8;

  FallPath(const BallState& entry, const Pocket& pocket, const PhysicsParams& params, double dt_max);
  /// fall_state(entry, pocket, params, dt).
  BallState state(double dt) const;

 private:
  BallState entry_;
  Vec3 centre_;
  double radius_;
  PhysicsParams params_;
  std::vector<Saved> saved_;  ///< after 0, kSaveEvery, 2 kSaveEvery, ... whole steps; last where it settles
};

}  // namespace bsim
