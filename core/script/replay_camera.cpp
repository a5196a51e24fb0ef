#include "replay_camera.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "camera_clearance.h"
#include "camera_view.h"
#include "cue_geometry.h"
#include "cue_script.h"
#include "director.h"
#include "table.h"

namespace bsim {

namespace {

/// s of simulation the replay holds on the balls at rest when they rest within kReplayTail of the drop.
constexpr double kRestHold = 0.25;
/// The pocket camera's places behind the pocket: m back from its centre along the ball's way, m above
/// the bed, and degrees turned off the ball's way; the first clear one that the movie did not use is taken.
struct PocketPlace {
  double back = 0, height = 0, turn_deg = 0;
};
constexpr PocketPlace kPocketPlaces[] = {{0.5, 0.2, 0},  {0.5, 0.2, 30},  {0.5, 0.2, -30},
                                         {0.9, 0.45, 0}, {0.9, 0.45, 35}, {0.9, 0.45, -35}};
/// The camera across the line of the shot: m from the line, m above the bed.
constexpr double kAcrossDistance = 1.5, kAcrossHeight = 0.6;
/// s before the winning ball drops that the camera stops turning after it and holds.
constexpr double kHoldBefore = 0.05;
/// s between the looks at the stick's share of a candidate's picture.
constexpr double kStickStep = 1.0 / 30.0;

struct Candidate {
  std::vector<CameraShot> shots;
  std::string what;
};

/// s where shot `shot`'s stretch ends: the next shot's start, or the end of the simulation.
double stretch_end(const Timeline& timeline, int shot) {
  const auto& shots = timeline.shots();
  return shot + 1 < static_cast<int>(shots.size()) ? shots[static_cast<std::size_t>(shot) + 1].start
                                                   : timeline.duration();
}

/// The winning ball's drop into a pocket within the shot's stretch.
std::optional<PocketDrop> winning_drop(const Timeline& timeline, const ReplaySubject& subject) {
  if (subject.ball < 0) return std::nullopt;
  const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(subject.shot)];
  for (const PocketDrop& drop : timeline.pocket_drops())
    if (drop.ball == subject.ball && drop.time >= span.start && drop.time <= stretch_end(timeline, subject.shot))
      return drop;
  return std::nullopt;
}

/// The first event of the shot of `type` that `ball` takes part in (any ball for -1), or nullptr.
const Event* first_event(const Timeline& timeline, int shot, EventType type, int ball) {
  for (const Event& e : timeline.events()) {
    if (e.shot != shot || e.type != type) continue;
    if (ball < 0 || std::find(e.balls.begin(), e.balls.end(), ball) != e.balls.end()) return &e;
  }
  return nullptr;
}

Vec3 horizontal(const Vec3& v) { return {v.x(), v.y(), 0.0}; }

Vec3 turned(const Vec3& v, double degrees) {
  const double a = degrees * kDegToRad;
  return {std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y(), v.z()};
}

CameraShot description(int event, CameraMode mode, const Vec3& location) {
  CameraShot shot;
  shot.event = event;
  shot.mode = mode;
  shot.location = location;
  return shot;
}

/// The way (unit, horizontal) the ball travels as it drops into its pocket.
Vec3 drop_way(const Scene& scene, const Timeline& timeline, const PocketDrop& drop) {
  const Vec3 velocity = horizontal(timeline.motion_state(drop.ball, drop.time - 0.02).velocity);
  if (velocity.norm() > 1e-3) return velocity.normalized();
  const Pocket& pocket = scene.pockets[static_cast<std::size_t>(drop.pocket)];
  const Vec3 axis = horizontal(pocket.axis);
  return axis.norm() > 1e-6 ? Vec3(axis.normalized()) : Vec3(1, 0, 0);
}

/// A camera at `location` from the strike: it frames the winning ball and the struck one, then, from
/// the winning ball's first contact, looks at it on its way, and as it drops holds on where it went in
/// (rather than look down the hole after it).
std::vector<CameraShot> watching(const Timeline& timeline, const ReplaySubject& subject, const Event& cue,
                                 const Vec3& location) {
  const double strike = cue.time;
  const int struck = cue.balls.empty() ? 0 : cue.balls.front();
  if (subject.ball < 0 || subject.ball == struck) {
    // No ball won it (a game won on a foul): the struck ball, from the strike.
    CameraShot look = description(cue.index, CameraMode::look, location);
    look.ball = struck;
    return {look};
  }
  CameraShot first = description(cue.index, CameraMode::hover, location);
  first.target = timeline.motion_state(subject.ball, strike).position;
  const Vec3 cue_ball = timeline.motion_state(struck, strike).position;
  if (!CameraView({location, first.target, false}).contains(cue_ball, 0.08))
    first.target = 0.5 * (first.target + cue_ball);
  const Event* hit = first_event(timeline, subject.shot, EventType::ball_ball, subject.ball);
  if (!hit) return {first};
  CameraShot follow = description(hit->index, CameraMode::look, location);
  follow.ball = subject.ball;
  follow.pre = 0.3;
  const std::optional<PocketDrop> drop = winning_drop(timeline, subject);
  if (!drop || drop->time <= hit->time + kHoldBefore) return {first, follow};
  CameraShot hold = description(0, CameraMode::hover, location);
  hold.key.kind = CameraKeyKind::at;  // s from the start of the simulation
  hold.key.seconds = drop->time - kHoldBefore;
  hold.target = timeline.motion_state(subject.ball, hold.key.seconds).position;
  return {first, follow, hold};
}

/// Pocket cameras behind the winning ball's pocket, then cameras across the line of the shot.
std::vector<Candidate> candidates(const Scene& scene, const Timeline& timeline, const ReplaySubject& subject,
                                  const Event& cue) {
  std::vector<Candidate> list;
  if (const std::optional<PocketDrop> drop = winning_drop(timeline, subject)) {
    const Vec3 way = drop_way(scene, timeline, *drop);
    const Vec3 centre = scene.pockets[static_cast<std::size_t>(drop->pocket)].center;
    const std::string pocket = pocket_name(scene.pockets, drop->pocket);
    for (const PocketPlace& place : kPocketPlaces) {
      const Vec3 location = horizontal(centre) + place.back * turned(way, place.turn_deg) + Vec3(0, 0, place.height);
      list.push_back({watching(timeline, subject, cue, location),
                      std::string(place.height < 0.3 ? "a camera low behind " : "a camera behind ") + pocket});
    }
  }
  const int struck = cue.balls.empty() ? 0 : cue.balls.front();
  Vec3 line = cue.after.empty() ? Vec3(1, 0, 0) : horizontal(cue.after.front().velocity);
  line = line.norm() > 1e-6 ? Vec3(line.normalized()) : Vec3(1, 0, 0);
  const Vec3 middle = horizontal(timeline.motion_state(struck, cue.time).position) + 0.5 * line;
  for (const double side : {1.0, -1.0}) {
    const Vec3 across = side * Vec3(-line.y(), line.x(), 0.0);
    list.push_back({watching(timeline, subject, cue, middle + kAcrossDistance * across + Vec3(0, 0, kAcrossHeight)),
                    "a camera across the line of the shot"});
  }
  return list;
}

/// Degrees between two views seen from above; 180 when either looks (nearly) straight down.
double angle_between(const CameraPose& a, const CameraPose& b) {
  const Vec3 u = horizontal(a.look_at - a.location), v = horizontal(b.look_at - b.location);
  if (u.norm() < 1e-6 || v.norm() < 1e-6) return 180.0;
  return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) / kDegToRad;
}

/// The most of `camera`'s picture the stick covers while at the ball (its address to its follow-through,
/// the same whatever camera films it) within the replayed stretch [from, to].
double stick_share(const CameraScript& camera, const std::optional<CueStroke>& stroke, double from, double to) {
  double most = 0;
  if (!stroke) return most;
  const AtBall at = at_ball(*stroke);
  for (double t = std::max(at.begin, from); t <= std::min(at.end, to); t += kStickStep)
    most = std::max(most, stick_picture_share(stroke_pose(*stroke, t), camera.pose(t)));
  return most;
}

/// Whether the candidate makes a script clear of everything over the whole timeline, looks from
/// elsewhere than `main` at `moment`, and is not blocked by the stick in the replayed stretch.
bool acceptable(const Scene& scene, const Timeline& timeline, const CameraScript& main, const Candidate& candidate,
                double moment, const std::optional<CueStroke>& stroke, const ReplayPlan& span) {
  std::vector<Diagnostic> diagnostics;
  const std::optional<CameraScript> script = CameraScript::build(scene, candidate.shots, timeline, diagnostics);
  if (!script || !diagnostics.empty()) return false;
  check_camera_clearance(scene, timeline, *script, diagnostics);
  if (!diagnostics.empty()) return false;
  if (stick_share(*script, stroke, span.start, span.end) > kDirectorStickShare) return false;
  return angle_between(script->pose(moment), main.pose(moment)) >= kReplayAngleDeg;
}

}  // namespace

ReplayPlan replay_span(const Timeline& timeline, const ReplaySubject& subject) {
  ReplayPlan plan;
  const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(subject.shot)];
  double until = span.rest + kRestHold;
  if (const std::optional<PocketDrop> drop = winning_drop(timeline, subject))
    until = std::min(until, drop->time + kReplayTail);
  const double start = std::max(0.0, span.cue - kReplayLead);
  // A whole number of seconds of movie, so that the replay's frames and sound keep to whole frames.
  const double seconds = std::max(1.0, std::ceil((until - start) / kReplayRate - 1e-9));
  plan.end = std::min(start + seconds * kReplayRate, timeline.duration());
  plan.start = std::max(0.0, plan.end - seconds * kReplayRate);
  return plan;
}

ReplayPlan plan_replay(const Scene& scene, const Timeline& timeline, const CameraScript& main,
                       const ReplaySubject& subject) {
  ReplayPlan plan = replay_span(timeline, subject);
  const Event* cue = first_event(timeline, subject.shot, EventType::cue, -1);
  const std::optional<PocketDrop> drop = winning_drop(timeline, subject);
  const double moment = drop ? drop->time : timeline.shots()[static_cast<std::size_t>(subject.shot)].cue;
  if (cue) {
    const std::optional<CueStroke> stroke = plan_stroke(scene, timeline, subject.shot);
    for (const Candidate& candidate : candidates(scene, timeline, subject, *cue)) {
      if (!acceptable(scene, timeline, main, candidate, moment, stroke, plan)) continue;
      plan.camera = candidate.shots;
      plan.what = candidate.what;
      return plan;
    }
  }
  plan.camera = {CameraScript::default_shot(scene)};
  plan.what = "the wide camera over the table";
  return plan;
}

}  // namespace bsim
