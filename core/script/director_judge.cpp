#include "director_judge.h"

#include <algorithm>
#include <cmath>

#include "camera_moment.h"
#include "camera_view.h"
#include "cue_geometry.h"
#include "cue_script.h"
#include "diagnostics.h"

namespace bsim::directing {

namespace {

/// Hz at which a candidate script is sampled (speed, clearance, what is in the picture).
constexpr double kGridHz = 120.0;
/// m/s below which a ball counts as at rest.
constexpr double kMovingSpeed = 1e-3;

/// What a candidate aims for: the share of its moving time a pocketed ball, or the cue ball, is in
/// the picture (above the checks' 80 % and 60 %).
constexpr double kPocketedTarget = 0.9;
constexpr double kCueTarget = 0.72;
/// Candidates evaluated at most for one description before the best so far is taken.
constexpr int kMaxTries = 90;

/// Samples of the grid between two looks at the stick's share of the picture (30 Hz: the practice
/// strokes take about half a second each).
constexpr std::size_t kStickEvery = 4;

bool over(const TableRect& r, const Vec3& p) {
  return p.x() >= r.x0 && p.x() <= r.x1 && p.y() >= r.y0 && p.y() <= r.y1;
}

}  // namespace

ShotSamples sample_shot(const Timeline& timeline, double radius) {
  ShotSamples out;
  const double duration = timeline.duration();
  const int balls = timeline.ball_count();
  const auto shots = static_cast<std::size_t>(std::max(1, timeline.shot_count()));
  out.drop_time.assign(shots,
                       std::vector<double>(static_cast<std::size_t>(balls), std::numeric_limits<double>::infinity()));
  for (const PocketDrop& d : timeline.pocket_drops()) {
    double& first = out.drop_time[static_cast<std::size_t>(timeline.shot_at(d.time))][static_cast<std::size_t>(d.ball)];
    first = std::min(first, d.time);
  }
  out.peak_speed.assign(shots, std::vector<double>(static_cast<std::size_t>(balls), 0.0));
  for (int i = 0; i / kGridHz <= duration + 1e-9; ++i) {
    const double t = std::min(i / kGridHz, duration);
    const auto shot = static_cast<std::size_t>(timeline.shot_at(t));
    const std::vector<double>& drop_time = out.drop_time[shot];
    std::vector<double>& peak_speed = out.peak_speed[shot];
    out.times.push_back(t);
    std::vector<Vec3> where;
    std::vector<char> shown, moving;
    for (int b = 0; b < balls; ++b) {
      const auto ball = static_cast<std::size_t>(b);
      const BallState s = timeline.motion_state(b, t);
      where.push_back(s.position);
      shown.push_back(s.position.z() >= -radius && s.motion != Motion::pocketed);
      const double speed = Vec3(s.velocity.x(), s.velocity.y(), 0).norm();
      const bool goes =
          speed > kMovingSpeed && s.motion != Motion::falling && s.motion != Motion::pocketed && t < drop_time[ball];
      moving.push_back(goes);
      if (goes) peak_speed[ball] = std::max(peak_speed[ball], speed);
    }
    out.where.push_back(std::move(where));
    out.shown.push_back(std::move(shown));
    out.moving.push_back(std::move(moving));
  }
  return out;
}

bool clear_of_room(const TableLayout& layout, const Vec3& p) {
  if (p.z() < layout.rail_top + 0.03) return false;
  if (p.z() > kRoom.ceiling - 0.25) return false;
  const TableRect room = layout.wood_outer.grown(kRoom.margin - 0.4);
  if (!over(room, p)) return false;
  if (over(layout.lamp.grown(0.1), p) && p.z() >= layout.lamp_bottom - 0.1) return false;
  return true;
}

double side_to_keep(const LineOfAction& line, const Vec3& previous) {
  const double side = line.side(previous);
  return std::abs(side) > kOnLine ? (side > 0 ? 1.0 : -1.0) : 0.0;
}

bool keeps_side(const LineOfAction& line, double wanted, const Vec3& p) { return wanted * line.side(p) >= -kOnLine; }

void hold_after(std::vector<CameraShot>& shots, std::size_t placed) {
  for (std::size_t k = placed + 1; k < shots.size(); ++k) {
    const CameraKey key = shots[k].key;
    shots[k] = shots[placed];
    shots[k].key = key;
    shots[k].pre = 0;
    shots[k].post = 0;
  }
}

Judge::Judge(const Scene& scene, const Timeline& timeline, const ShotSamples& samples, int shot, int subject)
    : scene_(scene),
      timeline_(timeline),
      samples_(samples),
      layout_(table_layout(scene)),
      radius_(scene.physics.ball_radius) {
  const auto k = static_cast<std::size_t>(shot);
  from_ = shot_stretch(timeline, shot).start;
  const int struck = scene.cues[std::min(k, scene.cues.size() - 1)].target;
  for (int b = 0; b < timeline.ball_count(); ++b) {
    const bool pocketed = std::isfinite(samples.drop_time[k][static_cast<std::size_t>(b)]);
    if (pocketed || b == struck) watched_.push_back({b, pocketed ? kPocketedTarget : kCueTarget});
  }
  // The stick at the cue ball as the stick script will play it (raised over a cushion or a ball as far
  // as it must be), from its address to its follow-through.
  stroke_ = plan_stroke(scene, timeline, shot);
  const auto watched = [&](int ball) {
    return ball == subject ||
           std::any_of(watched_.begin(), watched_.end(), [&](const Watched& w) { return w.ball == ball; });
  };
  for (const Event& e : timeline.events())
    if (e.type == EventType::ball_jaw && e.shot == shot && !e.balls.empty() && watched(e.balls[0]))
      knocks_.push_back({e.time, e.where});
}

std::optional<CameraScript> Judge::film(const std::vector<CameraShot>& shots) const {
  std::vector<Diagnostic> ignored;
  return CameraScript::build(scene_, shots, timeline_, ignored);
}

bool Judge::clear(const Vec3& p, std::size_t sample) const {
  if (!clear_of_room(layout_, p)) return false;
  const auto& where = samples_.where[sample];
  const auto& shown = samples_.shown[sample];
  for (std::size_t b = 0; b < where.size(); ++b)
    if (shown[b] && (p - where[b]).norm() < radius_ + kDirectorBallRoom + 0.005) return false;
  return true;
}

bool Judge::stick_blocks(const CameraPose& pose, double t) const {
  if (!stroke_) return false;
  const AtBall at = at_ball(*stroke_);
  return t >= at.begin && t <= at.end && stick_picture_share(stroke_pose(*stroke_, t), pose) > kDirectorStickShare;
}

std::optional<CameraPose> Judge::pose(const std::vector<CameraShot>& shots, double t) const {
  const std::optional<CameraScript> script = film(shots);
  if (!script) return std::nullopt;
  return script->pose(t);
}

Verdict Judge::evaluate(const std::vector<CameraShot>& shots, const std::vector<LineOfAction>& lines,
                        double limit) const {
  Verdict v;
  const std::optional<CameraScript> script = film(shots);
  if (!script) return v;
  for (const CameraWindow& w : script->windows()) {
    const CameraShot& s = shots[static_cast<std::size_t>(w.shot)];
    const bool cut = s.key.kind == CameraKeyKind::start && s.key.shot > 0 && s.pre == 0 && s.post == 0;
    if (!cut && w.end > w.begin && w.end - w.begin < kMinBlendSeconds) {
      v.hurried = true;
      return v;
    }
  }
  for (const CameraWindow& w : script->windows()) {
    if (w.begin > limit || w.end < from_) continue;
    const LineOfAction& line = lines[static_cast<std::size_t>(w.shot)];
    const double a = line.side(script->pose(w.begin).location), b = line.side(script->pose(w.end).location);
    if ((a > kOnLine && b < -kOnLine) || (a < -kOnLine && b > kOnLine)) return v;
  }
  const std::vector<double>& times = samples_.times;
  std::vector<int> seen(watched_.size(), 0), moving(watched_.size(), 0);
  double fastest = 0;
  Vec3 previous(0, 0, 0);
  const std::size_t first =
      static_cast<std::size_t>(std::lower_bound(times.begin(), times.end(), from_) - times.begin());
  for (std::size_t i = first; i < times.size() && times[i] <= limit; ++i) {
    const CameraPose pose = script->pose(times[i]);
    if (!clear(pose.location, i)) return v;
    if ((i - first) % kStickEvery == 0 && stick_blocks(pose, times[i])) return v;
    if (i > first) fastest = std::max(fastest, (pose.location - previous).norm() / (times[i] - times[i - 1]));
    previous = pose.location;
    for (std::size_t k = 0; k < watched_.size(); ++k) {
      const auto ball = static_cast<std::size_t>(watched_[k].ball);
      if (!samples_.moving[i][ball]) continue;
      ++moving[k];
      if (CameraView(pose).contains(samples_.where[i][ball], kPlanMargin)) ++seen[k];
    }
  }
  v.ok = true;
  v.max_speed = fastest;
  v.shortfall = 0;
  for (std::size_t k = 0; k < watched_.size(); ++k)
    if (moving[k] > 0) v.shortfall += std::max(0.0, watched_[k].target - double(seen[k]) / moving[k]);
  // Every knock on a jaw in the picture, at its instant: the share missed.
  int knocks = 0, missed = 0;
  for (const Knock& k : knocks_) {
    if (k.time < from_ || k.time > limit) continue;
    ++knocks;
    if (!CameraView(script->pose(k.time)).contains(k.where, kPlanMargin)) ++missed;
  }
  if (knocks > 0) v.shortfall += double(missed) / knocks;
  return v;
}

std::optional<Judge::Choice> Judge::choose_with(std::vector<CameraShot> shots, const std::vector<LineOfAction>& lines,
                                                std::size_t slot, const std::vector<CameraShot>& candidates,
                                                const std::vector<Timing>& timings, double limit) const {
  std::optional<Choice> best;
  int tries = 0;
  for (const CameraShot& candidate : candidates) {
    if (++tries > kMaxTries) break;
    for (const Timing& timing : timings) {
      CameraShot shot = candidate;
      shot.key = shots[slot].key;
      shot.pre = timing.pre;
      shot.post = timing.post;
      shots[slot] = shot;
      hold_after(shots, slot);
      const Verdict v = evaluate(shots, lines, limit);
      if (v.hurried) continue;  // a longer blend may do
      if (!v.ok) break;         // another window will hardly make it clear
      if (v.good()) return Choice{shot, 0.0};
      if (v.usable() && (!best || v.shortfall < best->shortfall)) best = Choice{shot, v.shortfall};
    }
  }
  return best;
}

std::optional<CameraShot> Judge::choose(const std::vector<CameraShot>& shots, const std::vector<LineOfAction>& lines,
                                        std::size_t slot, const std::vector<CameraShot>& candidates,
                                        const Timings& timings, double limit) const {
  std::optional<Choice> first = choose_with(shots, lines, slot, candidates, timings.usual, limit);
  if (first && first->shortfall <= 0) return first->shot;
  std::optional<Choice> second =
      timings.early.empty() ? std::nullopt : choose_with(shots, lines, slot, candidates, timings.early, limit);
  if (second && (!first || second->shortfall < first->shortfall)) return second->shot;
  if (first) return first->shot;
  return std::nullopt;
}

}  // namespace bsim::directing
