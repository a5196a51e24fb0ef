#include "pocket_fall.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bsim {

namespace {

/// s, longest a ball may hang on the lip before it drops (a ball entering at almost no speed).
constexpr double kMaxFall = 5.0;
/// Fraction of sqrt(g R) a ball at least has going over the lip, so a creeping ball does not hang there.
constexpr double kMinLipSpeed = 0.05;

class Fall {
 public:
  Fall(const BallState& entry, const Pocket& pocket, const PhysicsParams& params)
      : entry_(entry), centre_(pocket.center), params_(params) {
    const double R = params.ball_radius, g = params.g;
    const Vec3 v(entry.velocity.x(), entry.velocity.y(), 0);
    const double speed = v.norm();
    if (speed > 0) {
      heading_ = v / speed;
    } else {
      const Vec3 in(centre_.x() - entry.position.x(), centre_.y() - entry.position.y(), 0);
      heading_ = in.norm() > 0 ? Vec3(in.normalized()) : Vec3(1, 0, 0);
    }
    wall_ = std::max(0.0, pocket.radius - R);
    rest_z_ = entry.position.z() - kPocketDepth;
    const double lip_speed = std::max(speed, kMinLipSpeed * std::sqrt(g * R));
    // Rolling over the lip (energy of a sphere pivoting on an edge): the lip stops pushing when
    // cos(theta) = (10 + 7 v^2 / (g R)) / 17, which is theta = 0 for v >= sqrt(g R).
    release_cos_ = (10 + 7 * lip_speed * lip_speed / (g * R)) / 17;
    pivoting_ = release_cos_ < 1;
    lip_ = Vec3(entry.position.x(), entry.position.y(), entry.position.z() - R);
    theta_rate_ = lip_speed / R;
    position_ = entry.position;
    velocity_ = pivoting_ ? Vec3(lip_speed * heading_) : Vec3(v);
  }

  bool settled() const { return settled_; }
  double time() const { return t_; }

  /// Everything a step changes, to save and to resume from.
  FallPath::Saved saved() const { return {position_, velocity_, theta_, theta_rate_, t_, pivoting_, settled_}; }
  void resume(const FallPath::Saved& m) {
    position_ = m.position;
    velocity_ = m.velocity;
    theta_ = m.theta;
    theta_rate_ = m.theta_rate;
    t_ = m.t;
    pivoting_ = m.pivoting;
    settled_ = m.settled;
  }

  /// Advances by h (or less, stopping exactly where the ball settles).
  void step(double h) {
    if (settled_) return;
    const double R = params_.ball_radius, g = params_.g;
    if (pivoting_) {
      // Velocity Verlet on theta'' = (5/7) (g/R) sin(theta).
      const double accel = 5.0 / 7.0 * g / R;
      theta_rate_ += 0.5 * h * accel * std::sin(theta_);
      theta_ += h * theta_rate_;
      theta_rate_ += 0.5 * h * accel * std::sin(theta_);
      position_ = lip_ + R * (std::sin(theta_) * heading_ + Vec3(0, 0, std::cos(theta_)));
      velocity_ = R * theta_rate_ * (std::cos(theta_) * heading_ - Vec3(0, 0, std::sin(theta_)));
      if (std::cos(theta_) <= release_cos_) pivoting_ = false;
      t_ += h;
      return;
    }
    const Vec3 gravity(0, 0, -g);
    Vec3 next = position_ + h * velocity_ + 0.5 * h * h * gravity;
    if (next.z() <= rest_z_) {
      // Land exactly on the rest depth within this step.
      const double vz = velocity_.z();
      const double drop = position_.z() - rest_z_;
      const double dt = (vz + std::sqrt(std::max(0.0, vz * vz + 2 * g * drop))) / g;
      position_ = position_ + dt * velocity_ + 0.5 * dt * dt * gravity;
      position_.z() = rest_z_;
      t_ += dt;
      settled_ = true;
      return;
    }
    position_ = next;
    velocity_ += h * gravity;
    const Vec3 out(position_.x() - centre_.x(), position_.y() - centre_.y(), 0);
    const double r = out.norm();
    if (r >= wall_ && r > 0) {
      const Vec3 n = out / r;
      const double vn = velocity_.dot(n);
      if (vn > 0) velocity_ -= (1 + kPocketWallRestitution) * vn * n;
    }
    t_ += h;
  }

  BallState state() const {
    BallState s = entry_;
    s.position = position_;
    if (settled_) {
      s.velocity.setZero();
      s.spin.setZero();
      s.motion = Motion::pocketed;
    } else {
      s.velocity = velocity_;
      s.motion = Motion::falling;
    }
    return s;
  }

 private:
  BallState entry_;
  Vec3 centre_;
  PhysicsParams params_;
  Vec3 heading_{1, 0, 0};
  Vec3 lip_{0, 0, 0};
  Vec3 position_{0, 0, 0};
  Vec3 velocity_{0, 0, 0};
  double wall_ = 0;
  double rest_z_ = 0;
  double release_cos_ = 1;
  double theta_ = 0;
  double theta_rate_ = 0;
  double t_ = 0;
  bool pivoting_ = false;
  bool settled_ = false;
};

}  // namespace

double fall_duration(const BallState& entry, const Pocket& pocket, const PhysicsParams& params) {
  Fall fall(entry, pocket, params);
  while (!fall.settled() && fall.time() < kMaxFall) fall.step(kFallStep);
  return fall.time();
}

namespace {
/// fall_state from `fall` after `done` whole steps (at or before dt): the same steps and the same
/// last part step as from the entry, so the same state to the bit.
BallState finish_fall(Fall& fall, long done, double dt) {
  const auto steps = static_cast<long>(std::floor(dt / kFallStep));
  for (long i = done; i < steps && !fall.settled(); ++i) fall.step(kFallStep);
  const double rest = dt - fall.time();
  if (rest > 0 && !fall.settled()) fall.step(std::min(rest, kFallStep));
  return fall.state();
}
}  // namespace

BallState fall_state(const BallState& entry, const Pocket& pocket, const PhysicsParams& params, double dt) {
  Fall fall(entry, pocket, params);
  return finish_fall(fall, 0, dt);
}

FallEnd fall_end(const BallState& entry, const Pocket& pocket, const PhysicsParams& params) {
  // fall_duration's integration, keeping the state after each of its last few whole steps.
  constexpr long kKeep = 4;
  std::array<FallPath::Saved, kKeep> last{};
  Fall fall(entry, pocket, params);
  long count = 0;  ///< steps taken; last[c % kKeep] is the state after c of them
  last[0] = fall.saved();
  while (!fall.settled() && fall.time() < kMaxFall) {
    fall.step(kFallStep);
    ++count;
    last[static_cast<std::size_t>(count % kKeep)] = fall.saved();
  }
  FallEnd end;
  end.duration = fall.time();
  // fall_state at that duration takes floor(duration / step) whole steps (fewer where the ball settles),
  // then the part step left: resumed from the same steps here, or integrated again if they are gone.
  const long done = std::min(static_cast<long>(std::floor(end.duration / kFallStep)), count);
  if (count - done < kKeep) {
    fall.resume(last[static_cast<std::size_t>(done % kKeep)]);
    end.state = finish_fall(fall, done, end.duration);
  } else {
    end.state = fall_state(entry, pocket, params, end.duration);
  }
  return end;
}

FallPath::FallPath(const BallState& entry, const Pocket& pocket, const PhysicsParams& params, double dt_max)
    : entry_(entry), centre_(pocket.center), radius_(pocket.radius), params_(params) {
  Fall fall(entry, pocket, params);
  const auto steps = static_cast<long>(std::floor(std::max(0.0, dt_max) / kFallStep));
  saved_.push_back(fall.saved());
  for (long i = 1; i <= steps && !fall.settled(); ++i) {
    fall.step(kFallStep);
    if (i % kSaveEvery == 0 || fall.settled()) saved_.push_back(fall.saved());
  }
}

BallState FallPath::state(double dt) const {
  Fall fall(entry_, Pocket{centre_, radius_, {}}, params_);
  const auto steps = static_cast<long>(std::floor(dt / kFallStep));
  // The last save at or before `steps` whole steps (a settled fall stays as it is).
  const auto k = std::min(static_cast<std::size_t>(std::max(0L, steps) / kSaveEvery), saved_.size() - 1);
  fall.resume(saved_[k]);
  return finish_fall(fall, static_cast<long>(k) * kSaveEvery, dt);
}

}  // namespace bsim
