#include "ball_track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace bsim {

namespace {
/// s between samples of the path; fine enough that a sample never spans two rail hits.
constexpr double kSampleStep = 1.0 / 500.0;
/// m; chords shorter than this (a ball creeping to a stop, rounding) carry no usable direction.
constexpr double kMinChord = 1e-7;
/// m of path the heading averages over at least: a turn at a cushion is spread over this much travel.
constexpr double kTurnLength = 0.1;
/// s of recent motion the heading averages over at least, so a fast ball's camera still turns gently.
constexpr double kTurnTime = 0.5;

bool out_of_sight(const BallState& state, double radius) {
  return state.motion == Motion::pocketed || state.position.z() < -radius;
}
}  // namespace

BallTrack::BallTrack(const Timeline& timeline, int ball, std::optional<double> initial_heading_rad)
    : timeline_(&timeline), ball_(ball) {
  const double duration = timeline.duration();
  const double radius = timeline.physics().ball_radius;
  const int samples = static_cast<int>(std::ceil(duration / kSampleStep)) + 1;
  auto sample_time = [&](int i) { return std::min(i * kSampleStep, duration); };

  // Where the ball leaves the picture: the first sample out of sight, refined by bisection. The
  // samples in sight are kept: position() gives the same at those times.
  std::vector<Vec3> in_sight;
  in_sight.reserve(static_cast<std::size_t>(samples));
  hidden_time_ = std::numeric_limits<double>::infinity();
  for (int i = 0; i < samples; ++i) {
    const BallState state = motion_state(sample_time(i));
    if (!out_of_sight(state, radius)) {
      in_sight.push_back(state.position);
      continue;
    }
    if (i == 0) {
      hidden_time_ = 0;
      break;
    }
    double seen = sample_time(i - 1), unseen = sample_time(i);
    for (int k = 0; k < 60 && unseen - seen > 1e-12; ++k) {
      const double mid = 0.5 * (seen + unseen);
      (out_of_sight(motion_state(mid), radius) ? unseen : seen) = mid;
    }
    hidden_time_ = seen;
    break;
  }

  // The path as chords between samples: arc length, and the direction of each chord unwrapped so
  // that averaging angles over the path never jumps by a full turn.
  arc_.reserve(static_cast<std::size_t>(samples));
  arc_.push_back(0);
  bool have_angle = initial_heading_rad.has_value();
  initial_angle_ = initial_heading_rad.value_or(0.0);
  double last_angle = initial_angle_, integral = 0;
  // Every sample after those in sight is later than hidden_time_, where position() stays.
  const Vec3 last_seen = in_sight.size() < static_cast<std::size_t>(samples) ? position(hidden_time_) : Vec3(0, 0, 0);
  auto sample_position = [&](int i) {
    return static_cast<std::size_t>(i) < in_sight.size() ? in_sight[static_cast<std::size_t>(i)] : last_seen;
  };
  Vec3 previous = sample_position(0);
  for (int i = 1; i < samples; ++i) {
    const Vec3 here = sample_position(i);
    const double dx = here.x() - previous.x(), dy = here.y() - previous.y();
    previous = here;
    const double chord = std::hypot(dx, dy);
    if (!(chord > kMinChord)) {
      arc_.push_back(arc_.back());
      continue;
    }
    double angle = std::atan2(dy, dx);
    if (!have_angle) {
      initial_angle_ = angle;  // a ball never struck by the cue faces where it first goes
      have_angle = true;
    } else {
      angle = last_angle + std::remainder(angle - last_angle, 2.0 * std::numbers::pi);
    }
    last_angle = angle;
    knot_arc_.push_back(arc_.back());
    knot_integral_.push_back(integral);
    knot_angle_.push_back(angle);
    integral += angle * chord;
    arc_.push_back(arc_.back() + chord);
  }
  knot_arc_.push_back(arc_.back());
  knot_integral_.push_back(integral);
}

Vec3 BallTrack::position(double t) const { return motion_state(std::min(t, hidden_time_)).position; }

double BallTrack::arc_length(double t) const {
  const double duration = timeline_->duration();
  t = std::clamp(t, 0.0, duration);
  const auto last = static_cast<double>(arc_.size() - 1);
  const double index = std::min(std::floor(t / kSampleStep), last);
  const auto i = static_cast<std::size_t>(index);
  if (i + 1 >= arc_.size()) return arc_.back();
  const double t0 = index * kSampleStep, t1 = std::min(t0 + kSampleStep, duration);
  const double f = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
  return arc_[i] + f * (arc_[i + 1] - arc_[i]);
}

double BallTrack::angle_integral(double s) const {
  // Before the first motion the path is extended backwards along the initial heading.
  if (knot_angle_.empty() || s <= 0) return initial_angle_ * s;
  const auto it = std::upper_bound(knot_arc_.begin(), knot_arc_.end(), s);
  std::size_t k = static_cast<std::size_t>(it - knot_arc_.begin()) - 1;
  k = std::min(k, knot_angle_.size() - 1);
  return knot_integral_[k] + knot_angle_[k] * (s - knot_arc_[k]);
}

double BallTrack::heading_angle(double t) const {
  const double s = arc_length(t);
  const double span = std::max(kTurnLength, s - arc_length(t - kTurnTime));
  return (angle_integral(s) - angle_integral(s - span)) / span;
}

Vec3 BallTrack::heading(double t) const {
  const double angle = heading_angle(t);
  return Vec3(std::cos(angle), std::sin(angle), 0);
}

}  // namespace bsim
