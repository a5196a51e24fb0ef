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

BallTrack::BallTrack(const Timeline& timeline, int ball, std::optional<double> initial_heading_rad,
                     std::vector<TrackStrike> later)
    : timeline_(&timeline), ball_(ball) {
  const double duration = timeline.duration();
  const int samples = static_cast<int>(std::ceil(duration / kSampleStep)) + 1;
  auto sample_time = [&](int i) { return std::min(i * kSampleStep, duration); };
  const std::vector<Vec3> path = sample_path(samples);

  // The path as chords between samples: arc length, and the direction of each chord unwrapped so
  // that averaging angles over the path never jumps by a full turn. A ball put back on the bed (or
  // placed) at a later shot's start jumps there: no chord.
  std::vector<double> jumps;
  for (const ShotSpan& span : timeline.shots())
    if (span.start > 0) jumps.push_back(span.start);
  arc_.reserve(static_cast<std::size_t>(samples));
  arc_.push_back(0);
  bool have_angle = initial_heading_rad.has_value();
  initial_angle_ = initial_heading_rad.value_or(0.0);
  double last_angle = initial_angle_, integral = 0;
  for (int i = 1; i < samples; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const double dx = path[k].x() - path[k - 1].x(), dy = path[k].y() - path[k - 1].y();
    const double chord = std::hypot(dx, dy);
    const bool jump = std::any_of(jumps.begin(), jumps.end(),
                                  [&](double t) { return t > sample_time(i - 1) && t <= sample_time(i); });
    if (!(chord > kMinChord) || jump) {
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
  add_resets(later);
}

std::vector<Vec3> BallTrack::sample_path(int samples) {
  const double duration = timeline_->duration();
  const double radius = timeline_->physics().ball_radius;
  auto sample_time = [&](int i) { return std::min(i * kSampleStep, duration); };
  // Where the ball leaves the picture (the last sample in sight to the first out of it, refined by
  // bisection), and where a later shot puts it back: out of sight it stays at its last visible place.
  std::vector<Vec3> path;
  path.reserve(static_cast<std::size_t>(samples));
  bool hidden = false;
  for (int i = 0; i < samples; ++i) {
    const double t = sample_time(i);
    const BallState state = motion_state(t);
    const bool out = out_of_sight(state, radius);
    if (out == hidden) {
      path.push_back(out ? path.back() : state.position);
      continue;
    }
    if (out && i == 0) {
      hidden_.push_back({0, std::numeric_limits<double>::infinity()});
    } else {
      double seen = out ? sample_time(i - 1) : t, unseen = out ? t : sample_time(i - 1);
      for (int k = 0; k < 60 && std::abs(unseen - seen) > 1e-12; ++k) {
        const double mid = 0.5 * (seen + unseen);
        (out_of_sight(motion_state(mid), radius) ? unseen : seen) = mid;
      }
      if (out) hidden_.push_back({seen, std::numeric_limits<double>::infinity()});
      if (!out) hidden_.back().end = seen;
    }
    hidden = out;
    path.push_back(out ? motion_state(hidden_.back().begin).position : state.position);
  }
  return path;
}

void BallTrack::add_resets(const std::vector<TrackStrike>& later) {
  for (const TrackStrike& strike : later) {
    Reset r;
    r.from = strike.from;
    r.arc = arc_length(strike.time);
    // Unwrapped to the path after it (or before it, if the ball never moves again).
    const auto next = std::lower_bound(knot_arc_.begin(), knot_arc_.end() - 1, r.arc);
    const std::size_t k = static_cast<std::size_t>(next - knot_arc_.begin());
    const double near = knot_angle_.empty() ? initial_angle_ : knot_angle_[std::min(k, knot_angle_.size() - 1)];
    r.angle = near + std::remainder(strike.heading - near, 2.0 * std::numbers::pi);
    resets_.push_back(r);
  }
}

Vec3 BallTrack::position(double t) const {
  for (const Hidden& h : hidden_)
    if (t >= h.begin && t < h.end) return motion_state(h.begin).position;
  return motion_state(t).position;
}

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
  // After a later shot's start the path before its strike is the stick's line, as before the first.
  const Reset* reset = nullptr;
  for (const Reset& r : resets_)
    if (r.from <= t) reset = &r;
  if (reset && s - span < reset->arc)
    return (angle_integral(s) - angle_integral(reset->arc) + reset->angle * (reset->arc - (s - span))) / span;
  return (angle_integral(s) - angle_integral(s - span)) / span;
}

Vec3 BallTrack::heading(double t) const {
  const double angle = heading_angle(t);
  return Vec3(std::cos(angle), std::sin(angle), 0);
}

}  // namespace bsim
