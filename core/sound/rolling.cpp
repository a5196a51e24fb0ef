#include "rolling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "camera_interpolation.h"
#include "motion.h"
#include "simulate.h"
#include "sound_mix.h"
#include "sound_synth.h"

namespace bsim {

namespace {

constexpr double kRollLevel = 0.0015;     ///< RMS of the rumble at 1 m/s
constexpr double kRollExponent = 1.2;     ///< the rumble's amplitude grows as speed^1.2
constexpr double kSlipLevel = 0.0005;     ///< RMS of the slip hiss at 1 m/s of slip
constexpr double kHissQ = 2.0;            ///< sharpness of the slip hiss's band
constexpr double kBedMode = 105.0;        ///< Hz, the slate bed's low resonance the rumble rings
constexpr double kContactPatch = 0.003;   ///< m, radius of the ball's patch on the cloth: slip of a spin about z
constexpr double kTurnUnevenness = 0.25;  ///< depth of the once-a-turn modulation

/// Linear trapezoidal state-variable filter (Zavalishin, "The Art of VA Filter Design", 2012;
/// Simper, Cytomic 2013): stays stable while its cutoff moves.
class Svf {
 public:
  void tune(double cutoff, double q, int sample_rate) {
    const double g = std::tan(std::numbers::pi * std::min(cutoff, 0.45 * sample_rate) / sample_rate);
    k_ = 1 / q;
    a1_ = 1 / (1 + g * (g + k_));
    a2_ = g * a1_;
    a3_ = g * a2_;
  }
  /// Low-pass output; band() then holds the band-pass output scaled to unit peak gain.
  double process(double x) {
    const double v3 = x - ic2_;
    const double v1 = a1_ * ic1_ + a2_ * v3;
    const double v2 = ic2_ + a2_ * ic1_ + a3_ * v3;
    ic1_ = 2 * v1 - ic1_;
    ic2_ = 2 * v2 - ic2_;
    band_ = k_ * v1;
    return v2;
  }
  double band() const { return band_; }

 private:
  double k_ = 1, a1_ = 0, a2_ = 0, a3_ = 0;
  double ic1_ = 0, ic2_ = 0, band_ = 0;
};

/// Cutoff of the rumble at `roll` m/s: the cloth's roughness passes at speed / wavelength.
double rumble_cutoff(double roll, double muffle) { return (70.0 + 220.0 * std::min(roll, 4.0)) * (1 - 0.6 * muffle); }

/// Cutoff of the slip hiss.
double hiss_centre(double slip) { return 1500.0 + 400.0 * std::min(slip, 4.0); }

}  // namespace

double rumble_level(double roll) { return roll > 0 ? kRollLevel * std::pow(roll, kRollExponent) : 0.0; }

double slip_level(double slip) { return slip > 0 ? kSlipLevel * slip : 0.0; }

void render_rumble(const std::vector<RumblePoint>& points, double start, double ball_radius, std::uint64_t seed,
                   double muffle, AudioBuffer& out, std::vector<float>* send) {
  if (points.size() < 2) return;
  const int rate = out.sample_rate;
  const auto length = static_cast<long long>(std::min(out.left.size(), out.right.size()));
  SoundRandom random(seed);
  Svf rumble, bed, hiss;
  bed.tune(kBedMode, 2.0, rate);
  double turn = random.uniform();  // the phase of the ball's unevenness
  bool running = false;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const RumblePoint& p = points[k];
    const RumblePoint& q = points[k + 1];
    const long long first = std::llround((start + static_cast<double>(k) * kRumbleStep) * rate);
    const long long last = std::llround((start + static_cast<double>(k + 1) * kRumbleStep) * rate);
    // Unit-RMS scales: uniform noise has variance 1/3; a Butterworth low-pass passes 1.11 fc of
    // noise bandwidth, a unit-peak band-pass pi/2 fc/Q. They glide with the loudness, as a step in
    // them every millisecond would be a buzz.
    auto rumble_norm = [&](double roll) { return 1 / std::sqrt(1.0 / 3 * 2.22 * rumble_cutoff(roll, muffle) / rate); };
    auto hiss_norm = [&](double slip) {
      return 1 / std::sqrt(1.0 / 3 * std::numbers::pi * hiss_centre(slip) / kHissQ / rate);
    };
    const double roll0 = rumble_level(p.roll) * rumble_norm(p.roll), roll1 = rumble_level(q.roll) * rumble_norm(q.roll);
    const double slip0 = (1 - muffle) * slip_level(p.slip) * hiss_norm(p.slip);
    const double slip1 = (1 - muffle) * slip_level(q.slip) * hiss_norm(q.slip);
    if (roll0 == 0 && roll1 == 0 && slip0 == 0 && slip1 == 0) {
      running = false;  // silent: the filters start afresh when it moves again
      continue;
    }
    if (!running) {
      rumble = Svf{};
      hiss = Svf{};
      bed = Svf{};
      bed.tune(kBedMode, 2.0, rate);
      running = true;
    }
    const double roll = 0.5 * (p.roll + q.roll), slip = 0.5 * (p.slip + q.slip);
    const double cutoff = rumble_cutoff(roll, muffle), centre = hiss_centre(slip);
    rumble.tune(cutoff, 0.7071, rate);
    hiss.tune(centre, kHissQ, rate);
    const double turn_rate = roll / (2 * std::numbers::pi * ball_radius) / rate;  // turns per sample
    for (long long i = std::max(first, 0LL); i < last && i < length; ++i) {
      const double f = static_cast<double>(i - first) / static_cast<double>(last - first);
      const double noise = random.signed_unit();
      const double low = rumble.process(noise);
      bed.process(low);
      hiss.process(noise);
      turn += turn_rate;
      turn -= std::floor(turn);
      const double uneven = 1 + kTurnUnevenness * std::sin(2 * std::numbers::pi * turn);
      const double s = (roll0 + f * (roll1 - roll0)) * uneven * 0.75 * (low + 0.9 * bed.band()) +
                       (slip0 + f * (slip1 - slip0)) * hiss.band();
      const auto at = static_cast<std::size_t>(i);
      out.left[at] += static_cast<float>((p.left + f * (q.left - p.left)) * s);
      out.right[at] += static_cast<float>((p.right + f * (q.right - p.right)) * s);
      if (send && at < send->size()) (*send)[at] += static_cast<float>((p.send + f * (q.send - p.send)) * s);
    }
  }
}

void mix_rolling(const SoundSource& shot, AudioBuffer& out, std::vector<float>* send) {
  const Timeline& timeline = shot.timeline;
  const PhysicsParams& physics = timeline.physics();
  const auto steps = static_cast<std::size_t>(std::ceil(timeline.duration() / kRumbleStep)) + 1;
  std::vector<CameraPose> poses(steps);
  for (std::size_t k = 0; k < steps; ++k) poses[k] = shot.camera.pose(static_cast<double>(k) * kRumbleStep);
  for (int ball = 0; ball < timeline.ball_count(); ++ball) {
    std::vector<RumblePoint> points(steps);
    bool heard = false;
    for (std::size_t k = 0; k < steps; ++k) {
      const double t = std::min(static_cast<double>(k) * kRumbleStep, timeline.duration());
      const BallState s = timeline.motion_state(ball, t);
      RumblePoint& p = points[k];
      const double spin_slip = std::abs(s.spin.z()) * kContactPatch;
      switch (s.motion) {
        case Motion::rolling:
          p.roll = std::hypot(s.velocity.x(), s.velocity.y());
          p.slip = spin_slip;
          break;
        case Motion::sliding:
          p.roll = std::hypot(s.velocity.x(), s.velocity.y());
          p.slip = contact_slip(s, physics).norm() + spin_slip;
          break;
        case Motion::spinning: p.slip = spin_slip; break;
        default: break;
      }
      if (p.roll == 0 && p.slip == 0) continue;
      heard = true;
      const Placement place = placement(poses[k], s.position);
      p.left = place.left;
      p.right = place.right;
      p.send = place.send;
    }
    if (!heard) continue;
    const std::uint64_t seed = 0x7f4a7c15ULL * static_cast<std::uint64_t>(ball + 1) ^ 0xd1b54a32d192ed03ULL;
    render_rumble(points, 0.0, physics.ball_radius, seed, 0.0, out, send);
  }
}

}  // namespace bsim
