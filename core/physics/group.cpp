#include "group.h"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
  alignas(16) double nx = 0;
  double ny = 0;       ///< (nx, ny): unit normal from i to j (frozen)
  double gap = 0;      ///< m, surface gap at the start (>= 0)
  double force = 0;    ///< N, at the last step
  double impulse = 0;  ///< N s, accumulated normal impulse
  double overlap = 0;  ///< m, at the last step (negative: apart)
  double v0 = 0;       ///< m/s, largest closing speed of the current contact
  int contact = -1;    ///< index into the contacts while in contact, else -1
};

/// The largest relative speed of two balls of the group (m/s), in the table's plane: the largest hypot of
/// their velocity differences. Only pairs whose squared difference lies within a part in 1e9 of the
/// largest can have it (hypot errs by under an ulp), so only theirs are taken.
double largest_relative_speed(const std::vector<BallState>& balls) {
  const int count = static_cast<int>(balls.size());
  auto difference = [&](int i, int j) {
    const BallState &a = balls[static_cast<std::size_t>(i)], &b = balls[static_cast<std::size_t>(j)];
    return std::pair(a.velocity.x() - b.velocity.x(), a.velocity.y() - b.velocity.y());
  };
  double largest2 = 0;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const auto [dx, dy] = difference(i, j);
      largest2 = std::max(largest2, dx * dx + dy * dy);
    }
  double relative_speed = 0;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const auto [dx, dy] = difference(i, j);
      if (dx * dx + dy * dy >= largest2 * (1 - 1e-9)) relative_speed = std::max(relative_speed, std::hypot(dx, dy));
    }
  return relative_speed;
}

/// The pairs that can touch during the phase: those whose surfaces are less than `reach` apart.
std::vector<Pair> nearby_pairs(const std::vector<BallState>& balls, double ball_radius, double reach) {
  const int count = static_cast<int>(balls.size());
  const double R = ball_radius;
  std::vector<Pair> pairs;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const BallState &a = balls[static_cast<std::size_t>(i)], &b = balls[static_cast<std::size_t>(j)];
      const double dx = b.position.x() - a.position.x(), dy = b.position.y() - a.position.y();
      // Farther than 2R + reach by a part in 1e9 (far beyond hypot's round-off): out of reach, as d says.
      if (dx * dx + dy * dy > (2 * R + reach) * (2 * R + reach) * (1 + 1e-9)) continue;
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
  return pairs;
}

/// The group's integration: the balls' displacements from their places at the group's instant and
/// their velocities, x and y interleaved, the accelerations of the last step, and the step's constants.
struct Phase {
  std::vector<double> x, v, acc;
  double dt = 0;       ///< s
  double k = 0;        ///< N/m^1.5, Hertz stiffness
  double mass = 0;     ///< kg, each ball's
  double damping = 0;  ///< Hunt-Crossley damping ratio
};

/// A vector in the bed plane, (x, y), held in one SSE2 register where there is one. Each operation acts
/// on x and y alone, as two scalar ones would (IEEE, lane by lane), so the values are the same to the bit;
/// it only takes fewer instructions, and the group's step is bound by their number.
#if defined(__SSE2__)
struct Plane {
  __m128d v;
};
Plane load(const double* p) { return {_mm_loadu_pd(p)}; }
void store(double* p, Plane a) { _mm_storeu_pd(p, a.v); }
Plane operator-(Plane a, Plane b) { return {_mm_sub_pd(a.v, b.v)}; }
Plane operator+(Plane a, Plane b) { return {_mm_add_pd(a.v, b.v)}; }
Plane operator*(Plane a, Plane b) { return {_mm_mul_pd(a.v, b.v)}; }
Plane operator*(double a, Plane b) { return {_mm_mul_pd(_mm_set1_pd(a), b.v)}; }
Plane operator/(Plane a, double b) { return {_mm_div_pd(a.v, _mm_set1_pd(b))}; }
/// x + y.
double sum(Plane a) { return _mm_cvtsd_f64(_mm_add_sd(a.v, _mm_unpackhi_pd(a.v, a.v))); }
#else
struct Plane {
  double x, y;
};
Plane load(const double* p) { return {p[0], p[1]}; }
void store(double* p, Plane a) {
  p[0] = a.x;
  p[1] = a.y;
}
Plane operator-(Plane a, Plane b) { return {a.x - b.x, a.y - b.y}; }
Plane operator+(Plane a, Plane b) { return {a.x + b.x, a.y + b.y}; }
Plane operator*(Plane a, Plane b) { return {a.x * b.x, a.y * b.y}; }
Plane operator*(double a, Plane b) { return {a * b.x, a * b.y}; }
Plane operator/(Plane a, double b) { return {a.x / b, a.y / b}; }
double sum(Plane a) { return a.x + a.y; }
#endif

/// The force of pair p at step `step` (Hunt & Crossley with Flores's damping), added to the
/// accelerations; a contact's start and its largest closing speed are noted in `contacts`. In the
/// plane's terms: overlap = nx (xi - xj) + ny (yi - yj) - gap, and so on.
void pair_force(Pair& p, Phase& s, long step, std::vector<GroupContact>& contacts) {
  const auto i = 2 * static_cast<std::size_t>(p.i), j = 2 * static_cast<std::size_t>(p.j);
  const Plane normal = load(&p.nx);
  const double overlap = sum(normal * (load(&s.x[i]) - load(&s.x[j]))) - p.gap;
  if (!(overlap > 0) && p.contact < 0 && p.force == 0) {
    // Apart now and at the last step: no force. What the steps below would add is zero: to the impulse
    // (>= +0) and to the accelerations, which start each step at +0 and so can never be -0, adding a
    // zero changes no bit.
    p.overlap = overlap;
    return;
  }
  const double rate = sum(normal * (load(&s.v[i]) - load(&s.v[j])));
  double force = 0;
  if (overlap > 0) {
    if (p.contact < 0) {
      // The contact begins: when the overlap crossed zero within this step.
      const double begun = (static_cast<double>(step - 1) + -p.overlap / (overlap - p.overlap)) * s.dt;
      p.contact = static_cast<int>(contacts.size());
      contacts.push_back({p.i, p.j, begun, 0.0});
      p.v0 = 0;
    }
    p.v0 = std::max(p.v0, rate);
    const double hunt_crossley = p.v0 > 0 ? 1 + s.damping * rate / p.v0 : 1.0;
    force = std::max(0.0, s.k * overlap * std::sqrt(overlap) * hunt_crossley);
  } else if (p.contact >= 0) {
    contacts[static_cast<std::size_t>(p.contact)].speed = p.v0;
    p.contact = -1;
  }
  p.impulse += 0.5 * (p.force + force) * s.dt;
  p.force = force;
  p.overlap = overlap;
  const Plane f = force * normal / s.mass;  // (force nx / mass, force ny / mass)
  store(&s.acc[i], load(&s.acc[i]) - f);
  store(&s.acc[j], load(&s.acc[j]) + f);
}

/// Velocity Verlet: half kick, drift, forces at the new positions (the damping with the half-step
/// velocity), half kick.
void verlet_step(Phase& s, std::vector<Pair>& pairs, long step, std::vector<GroupContact>& contacts) {
  for (std::size_t q = 0; q < s.x.size(); ++q) {
    s.v[q] += 0.5 * s.dt * s.acc[q];
    s.x[q] += s.dt * s.v[q];
    s.acc[q] = 0;
  }
  for (Pair& p : pairs) pair_force(p, s, step, contacts);
  for (std::size_t q = 0; q < s.x.size(); ++q) s.v[q] += 0.5 * s.dt * s.acc[q];
}

/// Done when nothing overlaps and no nearby pair is still closing: one that would close its gap
/// within as long again as the phase has lasted (`elapsed`) keeps it going.
bool still_going(const std::vector<Pair>& pairs, const std::vector<double>& v, double elapsed) {
  for (const Pair& p : pairs) {
    if (p.contact >= 0) return true;
    const auto i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
    const double closing = p.nx * (v[2 * i] - v[2 * j]) + p.ny * (v[2 * i + 1] - v[2 * j + 1]);
    if (closing > kMinClosingSpeed && -p.overlap < closing * elapsed) return true;
  }
  return false;
}

/// Energy is never gained: scales the touched balls' velocities `v` about their centre of mass (which
/// keeps the momentum) back to the energy they came in with if the integration added any.
void keep_energy(const std::vector<BallState>& balls, const std::vector<bool>& touched_balls, std::vector<double>& v) {
  const std::size_t n = balls.size();
  double before = 0, after = 0, vx = 0, vy = 0;
  int touched = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!touched_balls[i]) continue;
    ++touched;
    before += balls[i].velocity.x() * balls[i].velocity.x() + balls[i].velocity.y() * balls[i].velocity.y();
    after += v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1];
    vx += v[2 * i];
    vy += v[2 * i + 1];
  }
  if (!(touched > 0 && after > before)) return;
  vx /= touched;
  vy /= touched;
  const double centre = touched * (vx * vx + vy * vy);
  const double scale = after > centre ? std::sqrt(std::max(0.0, before - centre) / (after - centre)) : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!touched_balls[i]) continue;
    v[2 * i] = vx + scale * (v[2 * i] - vx);
    v[2 * i + 1] = vy + scale * (v[2 * i + 1] - vy);
  }
}

/// Friction between the balls: the pairwise model's capped Coulomb impulse, with each pair's
/// accumulated normal impulse, pair by pair in a fixed order, once the normal phase is over.
void apply_friction(const std::vector<Pair>& pairs, std::vector<BallState>& after, const PhysicsParams& params) {
  const double R = params.ball_radius;
  for (const Pair& p : pairs) {
    if (!(p.impulse > 0)) continue;
    BallState &a = after[static_cast<std::size_t>(p.i)], &b = after[static_cast<std::size_t>(p.j)];
    const Vec3 normal(p.nx, p.ny, 0);
    const Vec3 friction = ball_ball_friction(a, b, normal, p.impulse, params);
    apply_impulse(a, R * normal, -friction, params);
    apply_impulse(b, -R * normal, friction, params);
  }
}

}  // namespace

double group_gap(double speed, const PhysicsParams& params) {
  return kGroupGapRatio * hertz_compression(speed, params);
}

GroupResult resolve_group(const std::vector<BallState>& balls, const PhysicsParams& params, double steps_per_contact) {
  GroupResult result;
  result.after = balls;
  result.touched.assign(balls.size(), false);

  // The pairs that can touch during the phase: those less than twice the gap threshold apart at the
  // group's largest relative speed (the balls move by about that much in the phase). A pair farther
  // apart that meets later is an ordinary contact of the event loop.
  const double relative_speed = largest_relative_speed(balls);
  if (!(relative_speed > 0)) return result;
  std::vector<Pair> pairs = nearby_pairs(balls, params.ball_radius, 2 * group_gap(relative_speed, params));
  if (pairs.empty()) return result;

  const double e = params.e_ball;
  Phase s;
  s.damping = e > 0 ? std::min(8.0 * (1 - e) / (5.0 * e), kMaxDampingRatio) : kMaxDampingRatio;
  // The damping stiffens the compression by up to (1 + damping): shorten the step to match.
  const double refine = std::sqrt(1 + s.damping);
  s.dt = hertz_contact_time(relative_speed, params) / (steps_per_contact * refine);
  s.k = params.k_hertz;
  s.mass = params.ball_mass;
  const long max_steps = static_cast<long>(std::ceil(kGroupMaxContactTimes * steps_per_contact * refine));

  const std::size_t n = balls.size();
  s.x.assign(2 * n, 0.0);
  s.v.resize(2 * n);
  s.acc.assign(2 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    s.v[2 * i] = balls[i].velocity.x();
    s.v[2 * i + 1] = balls[i].velocity.y();
  }
  long step = 0;
  while (step < max_steps) {
    ++step;
    verlet_step(s, pairs, step, result.contacts);
    if (!still_going(pairs, s.v, static_cast<double>(step) * s.dt)) break;
  }
  for (Pair& p : pairs)
    if (p.contact >= 0) result.contacts[static_cast<std::size_t>(p.contact)].speed = p.v0;
  result.steps = step;
  result.duration = static_cast<double>(step) * s.dt;

  for (const Pair& p : pairs)
    if (p.impulse > 0) {
      result.touched[static_cast<std::size_t>(p.i)] = true;
      result.touched[static_cast<std::size_t>(p.j)] = true;
    }
  keep_energy(balls, result.touched, s.v);
  for (std::size_t i = 0; i < n; ++i) {
    if (!result.touched[i]) continue;
    result.after[i].velocity.x() = s.v[2 * i];
    result.after[i].velocity.y() = s.v[2 * i + 1];
  }
  if (params.has_ball_friction()) apply_friction(pairs, result.after, params);
  for (std::size_t i = 0; i < n; ++i)
    if (result.touched[i]) result.after[i] = classify(result.after[i], params);
  return result;
}

}  // namespace bsim
