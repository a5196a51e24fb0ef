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
/// s, the least a retraction is cut to when the next shot starts soon after the strike.
constexpr double kMinRetractTime = 0.2;
/// s before the next shot's start by which a stroke's stick is removed (when the shot lasts long enough).
constexpr double kLeaveMargin = 0.1;
/// rad the stick swings up about the contact point while out of play, tried in turn for its approach
/// and for its retraction: the first whose sweep keeps within kSweepShare of the picture (else the one
/// that covers least). 0: it slides in (or out) along its own line.
constexpr double kLifts[] = {60.0 * kDegToRad, 30.0 * kDegToRad, 0.0};
/// The most of the camera's picture (stick_picture_share) the stick may sweep across as it comes in
/// and as it leaves.
constexpr double kSweepShare = 0.05;
/// m behind the contact point tried for the out-of-play position, nearest first, until out of view.
constexpr double kAwayDistances[] = {1.2, 2.0, 3.0, 5.0, 8.0, 12.0};
/// m kept between the stick and anything it passes.
constexpr double kClearance = 0.002;
/// deg, the range of butt elevations tried, lowest first (a player keeps the stick as level as he can).
constexpr int kMinElevationDeg = 5, kMaxElevationDeg = 75;
/// s between the instants checked when removing the stick.
constexpr double kHideStep = 1.0 / 240.0;

double lerp(double a, double b, double f) { return a + (b - a) * f; }

/// The stick `behind` m behind the stroke's contact point along its axis, swung `lift` rad up about it.
CuePose place(const CueStroke& s, double behind, double lift) {
  const double angle = s.elevation + lift;
  CuePose pose;
  pose.axis = Vec3(-std::cos(angle) * s.heading.x(), -std::cos(angle) * s.heading.y(), std::sin(angle));
  pose.tip = s.contact + behind * pose.axis;
  pose.visible = true;
  return pose;
}

/// The times that split a stroke's lead (its shot's start to the strike) into its parts.
struct LeadTimes {
  double forward = 0;          ///< s, the forward stroke begins
  double approach_end = 0;     ///< s
  double stroke = 0;           ///< s, one practice stroke
  double backswing_begin = 0;  ///< s
  double retract_begin = 0;    ///< s
};

LeadTimes lead_times(const CueStroke& s) {
  LeadTimes l;
  l.forward = s.cue_time - s.accel_time;
  l.approach_end = s.start + kApproachShare * (l.forward - s.start);
  l.stroke = 0.5 * kStrokesShare * (l.forward - s.start);
  l.backswing_begin = l.approach_end + 2.0 * l.stroke;
  l.retract_begin = s.cue_time + s.follow_time;
  return l;
}

/// The stick of stroke `s` at time t (visible, whatever t).
CuePose path(const CueStroke& s, double t) {
  const LeadTimes l = lead_times(s);
  if (t < l.approach_end) {
    // Swung down and slid in from out of view; the swing ends before the slide so the tip arrives level.
    const double u = (std::max(t, s.start) - s.start) / (l.approach_end - s.start);
    return place(s, lerp(s.approach_from, kAddressGap, smooth(u)), s.approach_lift * (1.0 - smooth(u / 0.7)));
  }
  if (t < l.backswing_begin) {
    const double w = std::sin(std::numbers::pi * (t - l.approach_end) / l.stroke);
    return place(s, kAddressGap + s.amplitude * w * w, 0);
  }
  if (t < l.forward) {
    const double u = (t - l.backswing_begin) / (l.forward - l.backswing_begin);
    return place(s, lerp(kAddressGap, s.backswing, smooth(u)), 0);
  }
  if (t <= s.cue_time) {
    // Measured back from the strike so the tip is exactly on the ball at the cue event.
    const double before = s.cue_time - t;
    return place(s, s.tip_speed * before - 0.5 * s.tip_speed / s.accel_time * before * before, 0);
  }
  if (t < l.retract_begin) {
    const double after = t - s.cue_time;
    return place(s, -(s.tip_speed * after - 0.5 * s.tip_speed / s.follow_time * after * after), 0);
  }
  // Slid back first, then swung up, so the part past the contact point never dips toward the bed.
  const double u = std::min((t - l.retract_begin) / s.retract_time, 1.0);
  return place(s, lerp(-s.follow, s.retract_to, smooth(u)), s.retract_lift * smooth((u - 0.3) / 0.7));
}

/// The cameras that film the stick: the movie's, and over a stretch of the timeline another one too
/// (a game's replay films its winning shot again).
class Views {
 public:
  Views(const CameraScript& camera, const AlsoFilmed& also) : camera_(camera), also_(also) {}
  /// Whether any part of the stick can appear in either camera's picture at t.
  bool see(const CuePose& stick, double t) const {
    return stick_in_view(stick, camera_.pose(t)) || (films_again(t) && stick_in_view(stick, also_.camera->pose(t)));
  }
  /// The larger share of either camera's picture the stick covers at t.
  double share(const CuePose& stick, double t) const {
    const double main = stick_picture_share(stick, camera_.pose(t));
    return films_again(t) ? std::max(main, stick_picture_share(stick, also_.camera->pose(t))) : main;
  }

 private:
  bool films_again(double t) const { return also_.camera && t >= also_.begin && t <= also_.end; }
  const CameraScript& camera_;
  AlsoFilmed also_;
};

/// Plans one shot's stroke around its strike: its pose and timing (plan), then, against the camera
/// that films it, where the stick comes in from and when it is removed (plan_retraction).
class StrokePlanner {
 public:
  StrokePlanner(const Scene& scene, const Timeline& timeline, CueStroke& s)
      : scene_(scene), timeline_(timeline), cue_(scene.cues[static_cast<std::size_t>(s.shot)]), s_(s) {}

  void plan();
  /// When the stick slides back and swings up, and when it is removed (once out of view of `views`).
  void plan_retraction(const Views& views);

 private:
  /// The lowest elevation from `lowest_deg` (whole degrees above it) that clears, else the one that
  /// comes closest.
  void choose_elevation(double lowest_deg);
  /// m, where the tip's face centre meets the ball: on the axis through the centre, or with a stroke at
  /// its offsets across the stick.
  Vec3 tip_contact(const Vec3& centre, double radius) const;
  /// The plan for one elevation: back-swing, forward stroke and follow-through.
  void plan_stroke(double elevation);
  /// m, the least gap to the balls at rest and the cushions over the stroke, at the planned elevation.
  double stroke_clearance() const;
  /// Whether the tip stays off the struck ball as it leaves.
  bool follow_through_clear() const;

  const Scene& scene_;
  const Timeline& timeline_;
  const Cue& cue_;
  CueStroke& s_;
};

void StrokePlanner::plan() {
  const double heading = cue_.heading_deg * kDegToRad;
  s_.heading = Vec3(std::cos(heading), std::sin(heading), 0);
  double ball_speed = timeline_.motion_state(s_.target, s_.cue_time).velocity.norm();
  for (const Event& event : timeline_.events()) {
    if (event.type == EventType::cue && event.shot == s_.shot && event.speed > 0) ball_speed = event.speed;
  }
  s_.ball_speed = ball_speed;

  // A stroke gives the elevation, raised only as far as the cushion and the balls need; else the seed's
  // shot takes the lowest that clears from kMinElevationDeg.
  choose_elevation(cue_.stroke ? cue_.stroke->elevation_deg : kMinElevationDeg);
  // The struck ball must stay ahead of the tip (a very slow shot, or a velocity that disagrees with
  // the heading): shorten the follow-through until it does.
  for (int tries = 0; tries < 8 && !follow_through_clear(); ++tries) {
    s_.follow *= 0.5;
    s_.follow_time = 2.0 * s_.follow / s_.tip_speed;
  }
  if (!follow_through_clear()) s_.follow = s_.follow_time = 0;
}

void StrokePlanner::plan_retraction(const Views& views) {
  const double retract_begin = s_.cue_time + s_.follow_time;
  // Gone before the next shot's start, so that shot's stick can come in from where its player stands.
  s_.retract_time = kRetractTime;
  if (s_.next_start >= 0)
    s_.retract_time = std::clamp(s_.next_start - kLeaveMargin - retract_begin, kMinRetractTime, kRetractTime);
  const double retract_end = retract_begin + s_.retract_time;
  const double approach_end = lead_times(s_).approach_end;

  // Out of play: the nearest position swung up by `lift` that the camera cannot see at t.
  const auto away = [&](double t, double lift) {
    for (double distance : kAwayDistances) {
      if (!views.see(place(s_, distance, lift), t)) return distance;
    }
    return kAwayDistances[std::size(kAwayDistances) - 1];
  };
  // The most of the picture the stick covers from t0 until it is out of view or t1.
  const auto sweep = [&](double t0, double t1, bool until_hidden) {
    double most = 0;
    for (double t = t0; t < t1; t += kHideStep) {
      const CuePose pose = path(s_, t);
      if (until_hidden && !views.see(pose, t)) break;
      most = std::max(most, views.share(pose, t));
    }
    return most;
  };
  // Each way the first lift that sweeps little of the picture, else the one that sweeps least.
  double approach_best = 2, retract_best = 2, approach_lift = kLifts[0], retract_lift = kLifts[0];
  for (const double lift : kLifts) {
    s_.approach_lift = s_.retract_lift = lift;
    s_.approach_from = away(s_.start, lift);
    s_.retract_to = away(retract_end, lift);
    const double in = approach_best > kSweepShare ? sweep(s_.start, approach_end, false) : 2;
    const double out = retract_best > kSweepShare ? sweep(retract_begin, retract_end, true) : 2;
    if (in < approach_best) approach_best = in, approach_lift = lift;
    if (out < retract_best) retract_best = out, retract_lift = lift;
  }
  s_.approach_lift = approach_lift;
  s_.retract_lift = retract_lift;
  s_.approach_from = away(s_.start, approach_lift);
  s_.retract_to = away(retract_end, retract_lift);
  s_.hide_time = retract_end;
  for (double t = retract_begin; t < retract_end; t += kHideStep) {
    if (!views.see(path(s_, t), t)) {
      s_.hide_time = t;
      break;
    }
  }
  if (s_.next_start >= 0) s_.hide_time = std::min(s_.hide_time, s_.next_start);
}

void StrokePlanner::choose_elevation(double lowest_deg) {
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
  s_.clears = best_gap >= kClearance;
}

Vec3 StrokePlanner::tip_contact(const Vec3& centre, double radius) const {
  const Vec3 toward_butt = place(s_, 0, 0).axis;           // the axis does not depend on the contact point
  if (!cue_.stroke) return centre + radius * toward_butt;  // through the ball's centre
  // The stroke's offsets across the stick: side to the shooter's right, height up across the axis
  // (the frame of strike.h), so the tip touches the ball where the strike's impulse acts.
  const Stroke& stroke = *cue_.stroke;
  const Vec3 d = -toward_butt;
  const Vec3 right(s_.heading.y(), -s_.heading.x(), 0);
  const Vec3 up = right.cross(d);
  const double depth = std::sqrt(std::max(0.0, 1.0 - stroke.side * stroke.side - stroke.height * stroke.height));
  return centre + radius * (depth * toward_butt + stroke.side * right + stroke.height * up);
}

void StrokePlanner::plan_stroke(double elevation) {
  s_.elevation = elevation;
  // After the strike the ball leaves level at ball_speed; a steep tip closing on it faster than
  // ball_speed * cos(elevation) would follow it in, so steep strokes are slower.
  s_.tip_speed = std::max(
      std::min(s_.ball_speed / kBallToTipSpeed, kSteepSpeedShare * s_.ball_speed * std::cos(elevation)), kMinTipSpeed);
  if (cue_.stroke) s_.tip_speed = cue_.stroke->speed;  // the stroke's speed at impact
  // The struck ball where it stands at the strike (a later shot's: where the shot before left it).
  const Vec3 centre = timeline_.motion_state(s_.target, s_.cue_time).position;
  s_.contact = tip_contact(centre, timeline_.physics().ball_radius);

  // Constant acceleration from rest at the back-swing to tip_speed at contact.
  const double lead = s_.cue_time - s_.start;
  s_.backswing = std::clamp(0.5 * s_.tip_speed * kAccelTime, kMinBackswing, kMaxBackswing);
  s_.accel_time = std::min(2.0 * s_.backswing / s_.tip_speed, 0.4 * lead);
  s_.backswing = 0.5 * s_.tip_speed * s_.accel_time;

  // Constant deceleration after contact; the tip dips along the axis, so it must stop above the bed.
  const double above_bed = s_.contact.z() - kCueTipRadius * std::cos(elevation) - kClearance;
  s_.follow = std::min({kMaxFollow, kFollowFraction * s_.backswing, above_bed / std::sin(elevation)});
  s_.follow = std::max(s_.follow, 0.0);
  s_.follow_time = 2.0 * s_.follow / s_.tip_speed;
  // With a stroke the practice strokes grow with its speed too (a break is a long stroke, a touch a
  // short one); the seed's shots keep its fixed reach.
  s_.amplitude = cue_.stroke ? std::clamp(0.5 * s_.backswing, kMinBackswing, kMaxFollow) : kStrokeAmplitude;
}

double StrokePlanner::stroke_clearance() const {
  const double radius = timeline_.physics().ball_radius;
  // Before the strike every ball rests (a placed or put-back ball already in its place).
  const std::vector<BallState> resting = timeline_.states(0.5 * (s_.start + s_.cue_time));
  const double farthest = std::max(s_.backswing, kAddressGap + s_.amplitude);
  double gap = std::numeric_limits<double>::infinity();
  for (double behind = 0; behind <= farthest + 1e-9; behind += 0.005)
    gap = std::min(gap, stick_clearance(place(s_, behind, 0), scene_, resting, radius, s_.target));
  // During the follow-through the struck ball leaves and the others may start to move.
  for (int i = 0; i <= 8; ++i) {
    const double t = s_.cue_time + s_.follow_time * i / 8.0;
    gap = std::min(gap, stick_clearance(path(s_, t), scene_, timeline_.states(t), radius, s_.target));
  }
  return gap;
}

bool StrokePlanner::follow_through_clear() const {
  const double radius = timeline_.physics().ball_radius;
  for (int i = 1; i <= 16; ++i) {
    const double t = s_.cue_time + s_.follow_time * i / 16.0;
    if (stick_ball_gap(path(s_, t), timeline_.motion_state(s_.target, t).position, radius) < 0) return false;
  }
  return true;
}

}  // namespace

double CueStroke::elevation_deg() const { return elevation / kDegToRad; }

std::optional<CueStroke> plan_stroke(const Scene& scene, const Timeline& timeline, int shot) {
  const std::vector<ShotSpan>& shots = timeline.shots();
  const auto k = static_cast<std::size_t>(shot);
  if (shot < 0 || k >= shots.size() || k >= scene.cues.size()) return std::nullopt;
  CueStroke s;
  s.shot = shot;
  s.target = scene.cues[k].target;
  s.start = shots[k].start;
  s.cue_time = shots[k].cue;
  if (k + 1 < shots.size()) s.next_start = shots[k + 1].start;
  if (!(s.cue_time > s.start) || s.target < 0 || s.target >= static_cast<int>(scene.balls.size())) return std::nullopt;
  StrokePlanner(scene, timeline, s).plan();
  return s;
}

AtBall at_ball(const CueStroke& stroke) {
  const LeadTimes l = lead_times(stroke);
  return {l.approach_end, l.retract_begin};
}

CuePose stroke_pose(const CueStroke& stroke, double t) {
  const AtBall at = at_ball(stroke);
  return path(stroke, std::clamp(t, at.begin, at.end));
}

CueScript::CueScript(const Scene& scene, const Timeline& timeline, const CameraScript& camera, const AlsoFilmed& also)
    : timeline_(&timeline) {
  const Views views(camera, also);
  const std::vector<ShotSpan>& shots = timeline.shots();
  stroke_of_shot_.assign(shots.size(), -1);
  for (std::size_t k = 0; k < shots.size() && k < scene.cues.size(); ++k) {
    std::optional<CueStroke> planned = plan_stroke(scene, timeline, static_cast<int>(k));
    if (!planned) continue;
    CueStroke& s = *planned;
    StrokePlanner(scene, timeline, s).plan_retraction(views);
    stroke_of_shot_[k] = static_cast<int>(strokes_.size());
    strokes_.push_back(s);
    const LeadTimes l = lead_times(s);
    phases_.push_back({CuePhase::approach, s.start, l.approach_end, s.shot});
    phases_.push_back({CuePhase::preflight, l.approach_end, l.forward, s.shot});
    phases_.push_back({CuePhase::impact, l.forward, l.retract_begin, s.shot});
    phases_.push_back({CuePhase::retraction, l.retract_begin, s.hide_time, s.shot});
  }
}

const CueStroke& CueScript::first() const {
  static const CueStroke kNone;
  return strokes_.empty() ? kNone : strokes_.front();
}

CuePose CueScript::pose(double t) const {
  const int shot = timeline_->shot_at(t);
  if (shot < 0 || shot >= static_cast<int>(stroke_of_shot_.size())) return {};
  const int index = stroke_of_shot_[static_cast<std::size_t>(shot)];
  if (index < 0) return {};
  const CueStroke& s = strokes_[static_cast<std::size_t>(index)];
  CuePose pose = path(s, t);
  pose.visible = t < s.hide_time;
  return pose;
}

}  // namespace bsim
