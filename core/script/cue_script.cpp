#include "cue_script.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

#include "camera_interpolation.h"
#include "cue_geometry.h"
#include "cue_pose.h"

namespace bsim {

namespace {
/// m between the tip and the ball when the stick is addressed and between strokes.
constexpr double kAddressGap = 0.02;
/// m, reach of the practice strokes of a seed shot (a stroke's grow with its speed).
constexpr double kStrokeAmplitude = 0.09;
/// Ball speed over tip speed: a 0.54 kg stick on a 0.17 kg ball with tip restitution ~0.8.
constexpr double kBallToTipSpeed = 1.4;
/// m/s, least tip speed, so a barely-moving shot still has a stroke of sensible length.
constexpr double kMinTipSpeed = 0.1;
/// Most of ball speed * cos(elevation) a steep stroke's tip may have at the strike.
constexpr double kSteepSpeedShare = 0.9;
/// s of forward stroke for an ordinary shot; bounded by the back-swing limits below.
constexpr double kAccelTime = 0.25;
constexpr double kMinBackswing = 0.03;  ///< m
constexpr double kMaxBackswing = 0.3;   ///< m
/// m of follow-through at most, and as a fraction of the back-swing.
constexpr double kMaxFollow = 0.15;
constexpr double kFollowFraction = 0.5;
/// Shares of the lead time before the forward stroke: approach, two strokes, back-swing.
constexpr double kApproachShare = 0.4, kStrokesShare = 0.4;
/// s from the end of the follow-through to the stick's removal at the latest.
constexpr double kRetractTime = 1.2;
/// rad the stick swings up about the contact point while out of play.
constexpr double kLift = 60.0 * kDegToRad;
/// m behind the contact point tried for the out-of-play position, nearest first, until out of view.
constexpr double kAwayDistances[] = {1.2, 2.0, 3.0, 5.0, 8.0, 12.0};
/// m kept between the stick and anything it passes.
constexpr double kClearance = 0.002;
/// deg, the range of butt elevations tried, lowest first (a player keeps the stick as level as he can).
constexpr int kMinElevationDeg = 5, kMaxElevationDeg = 75;
/// s between the instants checked when removing the stick.
constexpr double kHideStep = 1.0 / 240.0;

double lerp(double a, double b, double f) { return a + (b - a) * f; }
}  // namespace

CueScript::CueScript(const Scene& scene, const Timeline& timeline, const CameraScript& camera)
    : scene_(&scene), timeline_(&timeline), camera_(&camera) {
  cue_time_ = timeline.cue_time();
  const int target = scene.cue().target;
  if (!(cue_time_ > 0) || target < 0 || target >= static_cast<int>(scene.balls.size())) return;

  const double heading = scene.cue().heading_deg * kDegToRad;
  heading_ = Vec3(std::cos(heading), std::sin(heading), 0);
  double ball_speed = scene.ball(target).velocity.norm();
  for (const Event& event : timeline.events()) {
    if (event.type == EventType::cue && event.speed > 0) ball_speed = event.speed;
  }
  ball_speed_ = ball_speed;

  // A stroke gives the elevation, raised only as far as the cushion and the balls need; else the seed's
  // shot takes the lowest that clears from kMinElevationDeg.
  choose_elevation(scene.cue().stroke ? scene.cue().stroke->elevation_deg : kMinElevationDeg);
  // The struck ball must stay ahead of the tip (a very slow shot, or a velocity that disagrees with
  // the heading): shorten the follow-through until it does.
  for (int tries = 0; tries < 8 && !follow_through_clear(); ++tries) {
    follow_ *= 0.5;
    follow_time_ = 2.0 * follow_ / tip_speed_;
  }
  if (!follow_through_clear()) follow_ = follow_time_ = 0;

  const double forward = cue_time_ - accel_time_;
  const double approach_end = kApproachShare * forward;
  const double retract_begin = cue_time_ + follow_time_;
  const double retract_end = retract_begin + kRetractTime;

  // Out of play: the nearest swung-up position the camera cannot see at that moment.
  auto away = [&](double t) {
    for (double distance : kAwayDistances) {
      if (!stick_in_view(place(distance, kLift), camera_->pose(t))) return distance;
    }
    return kAwayDistances[std::size(kAwayDistances) - 1];
  };
  approach_from_ = away(0.0);
  retract_to_ = away(retract_end);
  hide_time_ = retract_end;
  for (double t = retract_begin; t < retract_end; t += kHideStep) {
    if (!stick_in_view(path(t), camera_->pose(t))) {
      hide_time_ = t;
      break;
    }
  }

  phases_ = {{CuePhase::approach, 0.0, approach_end},
             {CuePhase::preflight, approach_end, forward},
             {CuePhase::impact, forward, retract_begin},
             {CuePhase::retraction, retract_begin, hide_time_}};
}

double CueScript::elevation_deg() const { return elevation_ / kDegToRad; }

void CueScript::choose_elevation(double lowest_deg) {
  // The lowest elevation from lowest_deg whose stroke clears everything, else the one that comes closest.
  double best_gap = -std::numeric_limits<double>::infinity(), best = lowest_deg;
  for (double degrees = lowest_deg; degrees <= std::max<double>(kMaxElevationDeg, lowest_deg);
       degrees = std::floor(degrees) + 1) {
    plan_stroke(degrees * kDegToRad);
    const double gap = stroke_clearance();
    if (gap > best_gap) best_gap = gap, best = degrees;
    if (gap >= kClearance) break;
  }
  plan_stroke(best * kDegToRad);
  clears_ = best_gap >= kClearance;
}

Vec3 CueScript::tip_contact(const Vec3& centre, double radius) const {
  const Vec3 toward_butt = place(0, 0).axis;                      // the axis does not depend on the contact point
  if (!scene_->cue().stroke) return centre + radius * toward_butt;  // through the ball's centre
  // The stroke's offsets across the stick: side to the shooter's right, height up across the axis
  // (the frame of strike.h), so the tip touches the ball where the strike's impulse acts.
  const Stroke& stroke = *scene_->cue().stroke;
  const Vec3 d = -toward_butt;
  const Vec3 right(heading_.y(), -heading_.x(), 0);
  const Vec3 up = right.cross(d);
  const double depth = std::sqrt(std::max(0.0, 1.0 - stroke.side * stroke.side - stroke.height * stroke.height));
  return centre + radius * (depth * toward_butt + stroke.side * right + stroke.height * up);
}

void CueScript::plan_stroke(double elevation) {
  elevation_ = elevation;
  // After the strike the ball leaves level at ball_speed_; a steep tip closing on it faster than
  // ball_speed_ * cos(elevation) would follow it in, so steep strokes are slower.
  tip_speed_ = std::max(std::min(ball_speed_ / kBallToTipSpeed, kSteepSpeedShare * ball_speed_ * std::cos(elevation)),
                        kMinTipSpeed);
  if (scene_->cue().stroke) tip_speed_ = scene_->cue().stroke->speed;  // the stroke's speed at impact
  const Vec3 centre = scene_->balls[static_cast<std::size_t>(scene_->cue().target)].position;
  contact_ = tip_contact(centre, timeline_->physics().ball_radius);

  // Constant acceleration from rest at the back-swing to tip_speed_ at contact.
  accel_time_ = kAccelTime;
  backswing_ = std::clamp(0.5 * tip_speed_ * accel_time_, kMinBackswing, kMaxBackswing);
  accel_time_ = std::min(2.0 * backswing_ / tip_speed_, 0.4 * cue_time_);
  backswing_ = 0.5 * tip_speed_ * accel_time_;

  // Constant deceleration after contact; the tip dips along the axis, so it must stop above the bed.
  const double above_bed = contact_.z() - kCueTipRadius * std::cos(elevation) - kClearance;
  follow_ = std::min({kMaxFollow, kFollowFraction * backswing_, above_bed / std::sin(elevation)});
  follow_ = std::max(follow_, 0.0);
  follow_time_ = 2.0 * follow_ / tip_speed_;
  // With a stroke the practice strokes grow with its speed too (a break is a long stroke, a touch a
  // short one); the seed's shots keep its fixed reach.
  amplitude_ = scene_->cue().stroke ? std::clamp(0.5 * backswing_, kMinBackswing, kMaxFollow) : kStrokeAmplitude;
}

double CueScript::stroke_clearance() const {
  const double radius = timeline_->physics().ball_radius;
  // Before the strike every ball rests; the stick only slides along its line.
  const std::vector<BallState> resting = timeline_->states(0);
  const double farthest = std::max(backswing_, kAddressGap + amplitude_);
  double gap = std::numeric_limits<double>::infinity();
  for (double behind = 0; behind <= farthest + 1e-9; behind += 0.005)
    gap = std::min(gap, stick_clearance(place(behind, 0), *scene_, resting, radius, scene_->cue().target));
  // During the follow-through the struck ball leaves and the others may start to move.
  for (int i = 0; i <= 8; ++i) {
    const double t = cue_time_ + follow_time_ * i / 8.0;
    gap = std::min(gap, stick_clearance(path(t), *scene_, timeline_->states(t), radius, scene_->cue().target));
  }
  return gap;
}

bool CueScript::follow_through_clear() const {
  const double radius = timeline_->physics().ball_radius;
  const int target = scene_->cue().target;
  for (int i = 1; i <= 16; ++i) {
    const double t = cue_time_ + follow_time_ * i / 16.0;
    if (stick_ball_gap(path(t), timeline_->state(target, t).position, radius) < 0) return false;
  }
  return true;
}

CuePose CueScript::place(double behind, double lift) const {
  const double angle = elevation_ + lift;
  CuePose pose;
  pose.axis = Vec3(-std::cos(angle) * heading_.x(), -std::cos(angle) * heading_.y(), std::sin(angle));
  pose.tip = contact_ + behind * pose.axis;
  pose.visible = true;
  return pose;
}

CuePose CueScript::path(double t) const {
  const double forward = cue_time_ - accel_time_;
  const double approach_end = kApproachShare * forward;
  const double stroke = 0.5 * kStrokesShare * forward;
  const double backswing_begin = approach_end + 2.0 * stroke;
  const double retract_begin = cue_time_ + follow_time_;

  if (t < approach_end) {
    // Swung down and slid in from out of view; the swing ends before the slide so the tip arrives level.
    const double u = std::max(t, 0.0) / approach_end;
    return place(lerp(approach_from_, kAddressGap, smooth(u)), kLift * (1.0 - smooth(u / 0.7)));
  }
  if (t < backswing_begin) {
    const double s = std::sin(std::numbers::pi * (t - approach_end) / stroke);
    return place(kAddressGap + amplitude_ * s * s, 0);
  }
  if (t < forward) {
    const double u = (t - backswing_begin) / (forward - backswing_begin);
    return place(lerp(kAddressGap, backswing_, smooth(u)), 0);
  }
  if (t <= cue_time_) {
    // Measured back from the strike so the tip is exactly on the ball at the cue event.
    const double before = cue_time_ - t;
    return place(tip_speed_ * before - 0.5 * tip_speed_ / accel_time_ * before * before, 0);
  }
  if (t < retract_begin) {
    const double after = t - cue_time_;
    return place(-(tip_speed_ * after - 0.5 * tip_speed_ / follow_time_ * after * after), 0);
  }
  // Slid back first, then swung up, so the part past the contact point never dips toward the bed.
  const double u = std::min((t - retract_begin) / kRetractTime, 1.0);
  return place(lerp(-follow_, retract_to_, smooth(u)), kLift * smooth((u - 0.3) / 0.7));
}

CuePose CueScript::pose(double t) const {
  if (phases_.empty()) return {};
  CuePose pose = path(t);
  pose.visible = t < hide_time_;
  return pose;
}

}  // namespace bsim
