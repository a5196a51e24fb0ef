#include "group.h"

#include <algorithm>
#include <cmath>

#include "detect.h"
#include "motion.h"
#include "resolve.h"

namespace bsim {

namespace {

/// Largest damping ratio 8 (1 - e) / (5 e) used: Flores's law is meant for e near 1; below e = 0.14 the
/// phase stays well posed (the step shrinks with the damping) but no longer reproduces e_ball.
constexpr double kMaxDampingRatio = 10;

struct Pair {
  int i = 0, j = 0;
  double nx = 0, ny = 0;  ///< unit normal from i to j (frozen)
  double gap = 0;         ///< m, surface gap at the start (>= 0)
  double force = 0;       ///< N, at the last step
  double impulse = 0;     ///< N s, accumulated normal impulse
  double overlap = 0;     ///< m, at the last step (negative: apart)
  double v0 = 0;          ///< m/s, largest closing speed of the current contact
  int contact = -1;       ///< index into the contacts while in contact, else -1
};

}  // namespace

double hertz_compression(double speed, const PhysicsParams& params) {
  const double reduced_mass = 0.5 * params.ball_mass;
  return std::pow(5.0 * reduced_mass * speed * speed / (4.0 * params.k_hertz), 0.4);
}

double hertz_contact_time(double speed, const PhysicsParams& params) {
  return kHertzTimeFactor * hertz_compression(speed, params) / speed;
}

double group_gap(double speed, const PhysicsParams& params) {
  return kGroupGapRatio * hertz_compression(speed, params);
}

GroupResult resolve_group(const std::vector<BallState>& balls, const PhysicsParams& params, double steps_per_contact) {
  const int count = static_cast<int>(balls.size());
  const double R = params.ball_radius, m = params.ball_mass, k = params.k_hertz;
  GroupResult result;
  result.after = balls;
  result.touched.assign(balls.size(), false);

  // The pairs that can touch during the phase: those less than twice the gap threshold apart at the
  // group's largest relative speed (the balls move by about that much in the phase). A pair farther
  // apart that meets later is an ordinary contact of the event loop.
  double relative_speed = 0;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const BallState &a = balls[static_cast<std::size_t>(i)], &b = balls[static_cast<std::size_t>(j)];
      relative_speed =
          std::max(relative_speed, std::hypot(a.velocity.x() - b.velocity.x(), a.velocity.y() - b.velocity.y()));
    }
  if (!(relative_speed > 0)) return result;
  const double reach = 2 * group_gap(relative_speed, params);
  std::vector<Pair> pairs;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const BallState &a = balls[static_cast<std::size_t>(i)], &b = balls[static_cast<std::size_t>(j)];
      const double dx = b.position.x() - a.position.x(), dy = b.position.y() - a.position.y();
      const double d = std::hypot(dx, dy);
      if (!(d > 0) || d - 2 * R >= reach) continue;
      Pair p;
      p.i = i;
      p.j = j;
      p.nx = dx / d;
      p.ny = dy / d;
      p.gap = std::max(0.0, d - 2 * R);
      p.overlap = -p.gap;
      pairs.push_back(p);
    }
  if (pairs.empty()) return result;

  const double e = params.e_ball;
  const double damping = e > 0 ? std::min(8.0 * (1 - e) / (5.0 * e), kMaxDampingRatio) : kMaxDampingRatio;
  // The damping stiffens the compression by up to (1 + damping): shorten the step to match.
  const double refine = std::sqrt(1 + damping);
  const double dt = hertz_contact_time(relative_speed, params) / (steps_per_contact * refine);
  const long max_steps = static_cast<long>(std::ceil(kGroupMaxContactTimes * steps_per_contact * refine));

  const auto n = static_cast<std::size_t>(count);
  std::vector<double> x(2 * n, 0.0), v(2 * n), acc(2 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    v[2 * i] = balls[i].velocity.x();
    v[2 * i + 1] = balls[i].velocity.y();
  }

  long step = 0;
  while (step < max_steps) {
    ++step;
    // Velocity Verlet: half kick, drift, forces at the new positions (the damping with the half-step
    // velocity), half kick.
    for (std::size_t q = 0; q < 2 * n; ++q) {
      v[q] += 0.5 * dt * acc[q];
      x[q] += dt * v[q];
      acc[q] = 0;
    }
    for (Pair& p : pairs) {
      const auto i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
      const double overlap = p.nx * (x[2 * i] - x[2 * j]) + p.ny * (x[2 * i + 1] - x[2 * j + 1]) - p.gap;
      const double rate = p.nx * (v[2 * i] - v[2 * j]) + p.ny * (v[2 * i + 1] - v[2 * j + 1]);
      double force = 0;
      if (overlap > 0) {
        if (p.contact < 0) {
          // The contact begins: when the overlap crossed zero within this step.
          const double begun = (static_cast<double>(step - 1) + -p.overlap / (overlap - p.overlap)) * dt;
          p.contact = static_cast<int>(result.contacts.size());
          result.contacts.push_back({p.i, p.j, begun, 0.0});
          p.v0 = 0;
        }
        p.v0 = std::max(p.v0, rate);
        const double hunt_crossley = p.v0 > 0 ? 1 + damping * rate / p.v0 : 1.0;
        force = std::max(0.0, k * overlap * std::sqrt(overlap) * hunt_crossley);
      } else if (p.contact >= 0) {
        result.contacts[static_cast<std::size_t>(p.contact)].speed = p.v0;
        p.contact = -1;
      }
      p.impulse += 0.5 * (p.force + force) * dt;
      p.force = force;
      p.overlap = overlap;
      const double fx = force * p.nx / m, fy = force * p.ny / m;
      acc[2 * i] -= fx;
      acc[2 * i + 1] -= fy;
      acc[2 * j] += fx;
      acc[2 * j + 1] += fy;
    }
    for (std::size_t q = 0; q < 2 * n; ++q) v[q] += 0.5 * dt * acc[q];

    // Done when nothing overlaps and no nearby pair is still closing: one that would close its gap
    // within as long again as the phase has lasted keeps it going.
    bool going = false;
    const double elapsed = static_cast<double>(step) * dt;
    for (const Pair& p : pairs) {
      if (p.contact >= 0) {
        going = true;
        break;
      }
      const auto i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
      const double closing = p.nx * (v[2 * i] - v[2 * j]) + p.ny * (v[2 * i + 1] - v[2 * j + 1]);
      if (closing > kMinClosingSpeed && -p.overlap < closing * elapsed) {
        going = true;
        break;
      }
    }
    if (!going) break;
  }
  for (Pair& p : pairs)
    if (p.contact >= 0) result.contacts[static_cast<std::size_t>(p.contact)].speed = p.v0;
  result.steps = step;
  result.duration = static_cast<double>(step) * dt;

  for (const Pair& p : pairs)
    if (p.impulse > 0) {
      result.touched[static_cast<std::size_t>(p.i)] = true;
      result.touched[static_cast<std::size_t>(p.j)] = true;
    }

  // Energy is never gained: scale the touched balls' velocities about their centre of mass (which
  // keeps the momentum) back to the energy they came in with if the integration added any.
  double before = 0, after = 0, vx = 0, vy = 0;
  int touched = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!result.touched[i]) continue;
    ++touched;
    before += balls[i].velocity.x() * balls[i].velocity.x() + balls[i].velocity.y() * balls[i].velocity.y();
    after += v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1];
    vx += v[2 * i];
    vy += v[2 * i + 1];
  }
  if (touched > 0 && after > before) {
    vx /= touched;
    vy /= touched;
    const double centre = touched * (vx * vx + vy * vy);
    const double scale = after > centre ? std::sqrt(std::max(0.0, before - centre) / (after - centre)) : 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!result.touched[i]) continue;
      v[2 * i] = vx + scale * (v[2 * i] - vx);
      v[2 * i + 1] = vy + scale * (v[2 * i + 1] - vy);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!result.touched[i]) continue;
    result.after[i].velocity.x() = v[2 * i];
    result.after[i].velocity.y() = v[2 * i + 1];
  }

  // Friction between the balls: the pairwise model's capped Coulomb impulse, with each pair's
  // accumulated normal impulse, pair by pair in a fixed order, once the normal phase is over.
  if (params.mu_ball > 0)
    for (const Pair& p : pairs) {
      if (!(p.impulse > 0)) continue;
      BallState &a = result.after[static_cast<std::size_t>(p.i)], &b = result.after[static_cast<std::size_t>(p.j)];
      const Vec3 normal(p.nx, p.ny, 0);
      const Vec3 friction = ball_ball_friction(a, b, normal, p.impulse, params);
      apply_impulse(a, R * normal, -friction, params);
      apply_impulse(b, -R * normal, friction, params);
    }
  for (std::size_t i = 0; i < n; ++i)
    if (result.touched[i]) result.after[i] = classify(result.after[i], params);
  return result;
}

}  // namespace bsim
