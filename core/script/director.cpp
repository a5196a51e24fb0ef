#include "director.h"

// How the director shoots. Televised pool is covered in three beats, and the director writes one
// description for each:
//   1. the approach and the stroke from behind and above the cue ball, down the line of aim (the
//      "shooter's view" of broadcast pool), held until the cue ball meets its first object ball;
//   2. the ball that matters (the last object ball pocketed; else the cue ball if it is pocketed;
//      else the fastest object ball) on its run to the pocket, with a `look` from a high place (or a
//      `follow` when the ball is slow enough to walk beside), keyed at the contact that sets it going;
//   3. a wide shot of the whole table as the balls settle, from the moment it drops.
// Film grammar it keeps:
//   - the 180-degree rule: the camera stays on one side of the line of action (here the subject's
//     path at each description's key) from one description to the next (D. Arijon, "Grammar of the
//     Film Language", 1976, ch. 2; J. V. Mascelli, "The Five C's of Cinematography", 1965,
//     "Continuity": the action axis). A camera on the line itself (the shooter's view) is neutral
//     and may go to either side;
//   - a shot holds long enough to be read: no description spans less than kMinDescriptionSeconds
//     (R. Thompson and C. J. Bowen, "Grammar of the Edit", 2009: a shot needs time for the viewer to
//     take in its content);
//   - one camera, carried: every change is a blend (no cut), the camera never moves faster than a
//     person walks with it (kCameraCarrySpeed), keeps room around the balls and stays above the
//     table, below the ceiling and out of the lamp.
// Each placement is chosen from a fixed, ordered list of candidates by simulating the real camera
// (CameraScript::pose) over the shot: the first that keeps every pocketed ball and the cue ball in
// the picture long enough and breaks no rule wins, so the result is deterministic.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "camera_interpolation.h"
#include "camera_key.h"
#include "number_format.h"
#include "table.h"

namespace bsim {

namespace {

constexpr double kDeg = kDegToRad;  // the base's, under the director's short name
/// Hz at which a candidate script is sampled (speed, clearance, what is in the picture).
constexpr double kGridHz = 120.0;
/// m/s the director plans to: a margin under the bound, for what falls between samples.
constexpr double kPlanSpeed = 0.85 * kCameraCarrySpeed;
/// The share of the picture's width and height a watched ball keeps from its edges.
constexpr double kPlanMargin = 0.05;
/// What a candidate aims for: the share of its moving time a pocketed ball, or the cue ball, is in
/// the picture (above the checks' 80 % and 60 %).
constexpr double kPocketedTarget = 0.9;
constexpr double kCueTarget = 0.72;
/// m/s below which a ball counts as at rest.
constexpr double kMovingSpeed = 1e-3;
/// m from the line of action within which a camera counts as on it (neutral).
constexpr double kOnLine = 0.05;

/// The side of `line` a camera at `previous` stands on, to be kept by the next description: +1 left,
/// -1 right, 0 when it stands on the line (either side will do).
double side_to_keep(const LineOfAction& line, const Vec3& previous) {
  const double side = line.side(previous);
  return std::abs(side) > kOnLine ? (side > 0 ? 1.0 : -1.0) : 0.0;
}

/// Whether a camera at `p` is on the `wanted` side of `line` (or on the line).
bool keeps_side(const LineOfAction& line, double wanted, const Vec3& p) { return wanted * line.side(p) >= -kOnLine; }
/// Candidates evaluated at most for one description before the best so far is taken.
constexpr int kMaxTries = 90;

double mm(double v) { return std::round(v * 1000.0) / 1000.0; }
double hundredths(double v) { return std::round(v * 100.0) / 100.0; }
Vec3 mm(const Vec3& v) { return Vec3(mm(v.x()), mm(v.y()), mm(v.z())); }

Vec3 horizontal_unit(const Vec3& v, const Vec3& fallback) {
  const Vec3 h(v.x(), v.y(), 0);
  return h.norm() > 1e-9 ? Vec3(h / h.norm()) : fallback;
}

bool over(const TableRect& r, const Vec3& p) {
  return p.x() >= r.x0 && p.x() <= r.x1 && p.y() >= r.y0 && p.y() <= r.y1;
}

/// "the 8 (ball 5)", "the cue ball (ball 0)".
std::string ball_name(const Scene& scene, int ball) {
  const int number = scene.balls[static_cast<std::size_t>(ball)].number;
  return (number == 0 ? std::string("the cue ball") : "the " + std::to_string(number)) + " (ball " +
         std::to_string(ball) + ")";
}

CameraShot keyed(CameraKeyKind kind, int a = -1, int b = -1, int ordinal = 1, double seconds = 0) {
  CameraShot shot;
  shot.key.kind = kind;
  shot.key.a = a;
  shot.key.b = b;
  shot.key.ordinal = ordinal;
  shot.key.seconds = seconds;
  return shot;
}

/// What a candidate script does over the shot (up to a time limit).
struct Verdict {
  bool ok = false;  ///< clear of everything, on the right side of every line of action
  double max_speed = std::numeric_limits<double>::infinity();
  double shortfall = std::numeric_limits<double>::infinity();  ///< summed share below the targets
  bool good() const { return ok && max_speed <= kPlanSpeed && shortfall <= 0; }
  bool usable() const { return ok && max_speed <= kPlanSpeed; }
};

class Director {
 public:
  Director(const Scene& scene, const Timeline& timeline)
      : scene_(scene), timeline_(timeline), layout_(table_layout(scene)), radius_(scene.physics.ball_radius) {
    const double duration = timeline.duration();
    const int balls = timeline.ball_count();
    drop_time_.assign(static_cast<std::size_t>(balls), std::numeric_limits<double>::infinity());
    for (const PocketDrop& d : timeline.pocket_drops())
      drop_time_[static_cast<std::size_t>(d.ball)] = std::min(drop_time_[static_cast<std::size_t>(d.ball)], d.time);
    peak_speed_.assign(static_cast<std::size_t>(balls), 0.0);
    for (int i = 0; i / kGridHz <= duration + 1e-9; ++i) {
      const double t = std::min(i / kGridHz, duration);
      times_.push_back(t);
      std::vector<Vec3> where;
      std::vector<char> shown, moving;
      for (int b = 0; b < balls; ++b) {
        const BallState s = timeline.motion_state(b, t);
        where.push_back(s.position);
        shown.push_back(s.position.z() >= -radius_ && s.motion != Motion::pocketed);
        const double speed = Vec3(s.velocity.x(), s.velocity.y(), 0).norm();
        const bool goes = speed > kMovingSpeed && s.motion != Motion::falling && s.motion != Motion::pocketed &&
                          t < drop_time_[static_cast<std::size_t>(b)];
        moving.push_back(goes);
        if (goes) peak_speed_[static_cast<std::size_t>(b)] = std::max(peak_speed_[static_cast<std::size_t>(b)], speed);
      }
      where_.push_back(std::move(where));
      shown_.push_back(std::move(shown));
      moving_.push_back(std::move(moving));
    }
    cue_ball_ = scene.cue.target;
    for (int b = 0; b < balls; ++b) {
      const bool pocketed = std::isfinite(drop_time_[static_cast<std::size_t>(b)]);
      if (pocketed || b == cue_ball_) watched_.push_back({b, pocketed ? kPocketedTarget : kCueTarget});
    }
  }

  DirectedCamera run();

 private:
  struct Watched {
    int ball = 0;
    double target = 0;
  };
  struct Contact {
    double time = 0;
    int other = -1;
  };

  Vec3 at(int ball, double t) const { return timeline_.motion_state(ball, t).position; }
  Vec3 heading(int ball, double t, const Vec3& fallback) const {
    return horizontal_unit(timeline_.motion_state(ball, t).velocity, fallback);
  }

  /// Every contact of `ball` with another ball, in time order (a contact inside a group counting).
  std::vector<Contact> contacts(int ball) const {
    std::vector<Contact> found;
    for (const Event& e : timeline_.events()) {
      if (e.type != EventType::ball_ball) continue;
      for (const bsim::Contact& c : e.contacts)
        if (c.a == ball || c.b == ball) found.push_back({c.time, c.a == ball ? c.b : c.a});
    }
    std::stable_sort(found.begin(), found.end(), [](const Contact& x, const Contact& y) { return x.time < y.time; });
    return found;
  }

  std::optional<double> resolve(const CameraShot& shot) const {
    const KeyResolution r = resolve_camera_key(shot, scene_, timeline_);
    if (!r.instant) return std::nullopt;
    return r.instant->time;
  }

  /// Where the director never puts its camera: low over the table, near a ball, in the lamp, out of
  /// the room. `sample` < 0: the static part only.
  bool clear(const Vec3& p, int sample) const {
    if (p.z() < layout_.rail_top + 0.03) return false;
    if (p.z() > kRoom.ceiling - 0.25) return false;
    const TableRect room = layout_.wood_outer.grown(kRoom.margin - 0.4);
    if (!over(room, p)) return false;
    if (over(layout_.lamp.grown(0.1), p) && p.z() >= layout_.lamp_bottom - 0.1) return false;
    if (sample < 0) return true;
    const auto& where = where_[static_cast<std::size_t>(sample)];
    const auto& shown = shown_[static_cast<std::size_t>(sample)];
    for (std::size_t b = 0; b < where.size(); ++b)
      if (shown[b] && (p - where[b]).norm() < radius_ + kDirectorBallRoom + 0.005) return false;
    return true;
  }

  /// Simulates `shots` (the real CameraScript) up to `limit` and judges it.
  Verdict evaluate(const std::vector<CameraShot>& shots, const std::vector<LineOfAction>& lines, double limit) const {
    Verdict v;
    Scene copy = scene_;
    copy.camera = shots;
    std::vector<Diagnostic> ignored;
    const std::optional<CameraScript> script = CameraScript::build(copy, timeline_, ignored);
    if (!script) return v;
    for (const CameraWindow& w : script->windows()) {
      if (w.begin > limit) continue;
      const LineOfAction& line = lines[static_cast<std::size_t>(w.shot)];
      const double a = line.side(script->pose(w.begin).location), b = line.side(script->pose(w.end).location);
      if ((a > kOnLine && b < -kOnLine) || (a < -kOnLine && b > kOnLine)) return v;
    }
    std::vector<int> seen(watched_.size(), 0), moving(watched_.size(), 0);
    double fastest = 0;
    Vec3 previous(0, 0, 0);
    for (std::size_t i = 0; i < times_.size() && times_[i] <= limit; ++i) {
      const CameraPose pose = script->pose(times_[i]);
      if (!clear(pose.location, static_cast<int>(i))) return v;
      if (i > 0) fastest = std::max(fastest, (pose.location - previous).norm() / (times_[i] - times_[i - 1]));
      previous = pose.location;
      for (std::size_t k = 0; k < watched_.size(); ++k) {
        const auto ball = static_cast<std::size_t>(watched_[k].ball);
        if (!moving_[i][ball]) continue;
        ++moving[k];
        if (in_picture(pose, where_[i][ball], kPlanMargin)) ++seen[k];
      }
    }
    v.ok = true;
    v.max_speed = fastest;
    v.shortfall = 0;
    for (std::size_t k = 0; k < watched_.size(); ++k)
      if (moving[k] > 0) v.shortfall += std::max(0.0, watched_[k].target - double(seen[k]) / moving[k]);
    return v;
  }

  struct Timing {
    double pre = 0, post = 0;
  };
  struct Choice {
    CameraShot shot;
    double shortfall = 0;  ///< 0: it meets every target
  };

  /// The first candidate (in order) that is good with one of the timings (tried in order), else the
  /// usable one that misses the targets least. Candidates are complete descriptions but for their key
  /// and windows: the key is `slot`'s, the windows the timing's.
  std::optional<Choice> choose(std::vector<CameraShot> shots, const std::vector<LineOfAction>& lines, int slot,
                               const std::vector<CameraShot>& candidates, const std::vector<Timing>& timings,
                               double limit) const {
    const auto s = static_cast<std::size_t>(slot);
    std::optional<Choice> best;
    int tries = 0;
    for (const CameraShot& candidate : candidates) {
      if (++tries > kMaxTries) break;
      for (const Timing& timing : timings) {
        CameraShot shot = candidate;
        shot.key = shots[s].key;
        shot.pre = timing.pre;
        shot.post = timing.post;
        shots[s] = shot;
        // The descriptions after it hold the same camera until they are placed.
        for (std::size_t k = s + 1; k < shots.size(); ++k) {
          CameraKey key = shots[k].key;
          shots[k] = shot;
          shots[k].key = key;
          shots[k].pre = 0;
          shots[k].post = 0;
        }
        const Verdict v = evaluate(shots, lines, limit);
        if (!v.ok) break;  // another window will hardly make it clear
        if (v.good()) return Choice{shot, 0.0};
        if (v.usable() && (!best || v.shortfall < best->shortfall)) best = Choice{shot, v.shortfall};
      }
    }
    return best;
  }

  /// choose() with the usual timings first, then, if nothing meets every target, with `early` ones
  /// (blends that start sooner); the better of the two.
  std::optional<CameraShot> choose_timed(const std::vector<CameraShot>& shots, const std::vector<LineOfAction>& lines,
                                         int slot, const std::vector<CameraShot>& candidates,
                                         const std::vector<Timing>& usual, const std::vector<Timing>& early,
                                         double limit) const {
    std::optional<Choice> first = choose(shots, lines, slot, candidates, usual, limit);
    if (first && first->shortfall <= 0) return first->shot;
    std::optional<Choice> second = early.empty() ? std::nullopt : choose(shots, lines, slot, candidates, early, limit);
    if (second && (!first || second->shortfall < first->shortfall)) return second->shot;
    if (first) return first->shot;
    return std::nullopt;
  }

  const Scene& scene_;
  const Timeline& timeline_;
  TableLayout layout_;
  double radius_ = 0;
  int cue_ball_ = 0;
  std::vector<double> drop_time_, peak_speed_;
  std::vector<double> times_;
  std::vector<std::vector<Vec3>> where_;
  std::vector<std::vector<char>> shown_, moving_;
  std::vector<Watched> watched_;
};

DirectedCamera Director::run() {
  const double duration = timeline_.duration();
  const double cue_time = timeline_.cue_time();
  const int c = cue_ball_;
  const Ball& cue = scene_.balls[static_cast<std::size_t>(c)];
  const Vec3 c0 = cue.position;
  const double heading_rad = scene_.cue.heading_deg * kDeg;
  const Vec3 aim = horizontal_unit(cue.velocity, Vec3(std::cos(heading_rad), std::sin(heading_rad), 0));

  // The cue ball's first object ball.
  const std::vector<Contact> cue_contacts = contacts(c);
  const int first_object = cue_contacts.empty() ? -1 : cue_contacts.front().other;

  // The ball that matters: the last object ball pocketed, else the cue ball if it drops, else the
  // fastest object ball, else the cue ball.
  int subject = -1;
  double last_drop = -1;
  for (const PocketDrop& d : timeline_.pocket_drops())
    if (d.ball != c && d.time > last_drop) {
      last_drop = d.time;
      subject = d.ball;
    }
  if (subject < 0 && std::isfinite(drop_time_[static_cast<std::size_t>(c)])) subject = c;
  if (subject < 0) {
    double fastest = 0.05;
    for (int b = 0; b < timeline_.ball_count(); ++b)
      if (b != c && peak_speed_[static_cast<std::size_t>(b)] > fastest) {
        fastest = peak_speed_[static_cast<std::size_t>(b)];
        subject = b;
      }
  }
  if (subject < 0) subject = c;

  // Its key: the contact that first sets it moving (or the strike, for the cue ball).
  CameraShot subject_key = keyed(CameraKeyKind::cue);
  const std::vector<Contact> subject_contacts = contacts(subject);
  if (subject != c && !subject_contacts.empty())
    subject_key = keyed(CameraKeyKind::hit, subject_contacts.front().other, subject);
  std::optional<double> subject_time = resolve(subject_key);
  if (!subject_time) {
    subject_key = keyed(CameraKeyKind::cue);
    subject_time = resolve(subject_key);
  }

  // The wide closing shot: from the subject's drop, else its last contact, else a time as it slows.
  std::optional<CameraShot> wide_key;
  std::optional<double> wide_time;
  if (subject_time && duration - *subject_time >= 2 * kMinDescriptionSeconds) {
    const double earliest = *subject_time + kMinDescriptionSeconds, latest = duration - kMinDescriptionSeconds;
    std::vector<CameraShot> options;
    if (std::isfinite(drop_time_[static_cast<std::size_t>(subject)]))
      options.push_back(keyed(CameraKeyKind::pocket, subject));
    double last_contact = -1;
    CameraShot last_key;
    for (const Event& e : timeline_.events())
      if (e.type == EventType::ball_rail && !e.balls.empty() && e.balls[0] == subject && e.time > last_contact) {
        last_contact = e.time;
        last_key = keyed(CameraKeyKind::cushion, subject, -1, CameraKey::kLast);
      }
    if (!subject_contacts.empty() && subject_contacts.back().time > last_contact)
      last_key = keyed(CameraKeyKind::hit, subject_contacts.back().other, subject, CameraKey::kLast);
    if (last_contact >= 0 || !subject_contacts.empty()) options.push_back(last_key);
    for (const CameraShot& option : options) {
      const std::optional<double> t = resolve(option);
      if (t && *t >= earliest && *t <= latest) {
        wide_key = option;
        wide_time = t;
        break;
      }
    }
    if (!wide_key) {
      // As the subject slows below a walking pace, within the bounds.
      double slow = earliest;
      for (std::size_t i = 0; i < times_.size(); ++i)
        if (times_[i] >= earliest) {
          slow = times_[i];
          const Vec3 v = timeline_.motion_state(subject, times_[i]).velocity;
          if (Vec3(v.x(), v.y(), 0).norm() < 0.3) break;
        }
      const double seconds = std::ceil(std::clamp(slow, earliest, latest) * 100.0) / 100.0;
      if (seconds <= latest) {
        wide_key = keyed(CameraKeyKind::at, -1, -1, 1, seconds);
        wide_time = resolve(*wide_key);
      }
    }
  }
  const bool has_subject = subject_time && duration - *subject_time >= kMinDescriptionSeconds;

  // The keys and their lines of action.
  std::vector<CameraShot> shots = {keyed(CameraKeyKind::start)};
  std::vector<LineOfAction> lines = {{c0, aim}};
  std::vector<int> subjects = {c};
  if (has_subject) {
    CameraShot shot = subject_key;
    // The blend starts as the stick strikes (or at most 0.3 s before the key), never during the approach.
    const double start = std::max(cue_time, *subject_time - 0.3);
    shot.pre = *subject_time > 0 ? hundredths(std::max(0.0, (*subject_time - start) / *subject_time)) : 0.0;
    shots.push_back(shot);
    const double after = std::min(*subject_time + 1e-6, duration);
    lines.push_back({at(subject, *subject_time), heading(subject, after, aim)});
    subjects.push_back(subject);
    if (wide_key) {
      shots.push_back(*wide_key);
      const double before = std::max(*wide_time - 1e-6, 0.0);
      lines.push_back({at(subject, before), heading(subject, before, lines.back().direction)});
      subjects.push_back(subject);
    }
  }

  // 1. The approach and the stroke: a hover behind and above the cue ball, looking down the line of aim
  // at a point between it and its first object ball.
  const double reach =
      first_object >= 0
          ? std::clamp(0.45 * (scene_.balls[static_cast<std::size_t>(first_object)].position - c0).norm(), 0.2, 0.7)
          : 0.4;
  const Vec3 stroke_target = mm(Vec3(c0.x() + reach * aim.x(), c0.y() + reach * aim.y(), radius_));
  const double stroke_end = shots.size() > 1 ? *subject_time : duration;
  std::vector<CameraShot> stroke_options;
  for (double back : {0.8, 1.0, 1.25, 1.6, 2.0})
    for (double up : {0.45, 0.6, 0.8, 1.0}) {
      CameraShot s;
      s.mode = CameraMode::hover;
      s.location = mm(c0 - back * aim + Vec3(0, 0, up));
      s.target = stroke_target;
      if (clear(s.location, -1)) stroke_options.push_back(s);
    }
  bool stroke_placed = false;
  for (const CameraShot& option : stroke_options) {
    std::vector<CameraShot> trial = {option};
    const Verdict v = evaluate(trial, {lines[0]}, stroke_end);
    CameraPose pose{option.location, option.target, false};
    const bool frames = first_object < 0 ||
                        in_picture(pose, scene_.balls[static_cast<std::size_t>(first_object)].position, kPlanMargin);
    if (v.ok && frames && in_picture(pose, c0, kPlanMargin)) {
      shots[0].mode = option.mode;
      shots[0].location = option.location;
      shots[0].target = option.target;
      stroke_placed = true;
      break;
    }
  }
  if (!stroke_placed) {
    const CameraShot fallback = CameraScript::default_shot(scene_);
    shots[0].mode = fallback.mode;
    shots[0].location = mm(fallback.location);
    shots[0].target = mm(fallback.target);
  }
  // Until placed, the later descriptions hold the stroke's camera.
  for (std::size_t k = 1; k < shots.size(); ++k) {
    const CameraKey key = shots[k].key;
    const double pre = shots[k].pre;
    shots[k] = shots[0];
    shots[k].key = key;
    shots[k].pre = pre;
  }

  // 2. The ball that matters, to its pocket.
  if (shots.size() > 1) {
    const double t0 = *subject_time;
    const double t1 = wide_time ? *wide_time : duration;
    const Vec3 from = at(subject, t0);
    const Vec3 to = at(subject, std::min(t1, drop_time_[static_cast<std::size_t>(subject)]));
    const Vec3 middle = 0.5 * (from + to);
    const Vec3 previous = shots[0].location;
    const LineOfAction& line = lines[1];
    const double wanted = side_to_keep(line, previous);
    struct Option {
      double cost = 0;
      CameraShot shot;
    };
    std::vector<Option> options;
    const auto add_look = [&](const Vec3& location, double cost) {
      const Vec3 p = mm(location);
      if (!clear(p, -1) || !keeps_side(line, wanted, p)) return;
      CameraShot s;
      s.mode = CameraMode::look;
      s.location = p;
      s.ball = subject;
      options.push_back({cost, s});
    };
    for (double distance : {1.0, 1.4, 1.9, 2.5, 3.2})
      for (double elevation : {50.0, 38.0, 62.0})
        for (int a = 0; a < 24; ++a) {
          const double azimuth = a * 15.0 * kDeg;
          const Vec3 location = middle + distance * Vec3(std::cos(azimuth), std::sin(azimuth), 0) +
                                Vec3(0, 0, distance * std::tan(elevation * kDeg));
          add_look(location, distance + 0.5 * (location - previous).norm() + 0.8 * std::abs(elevation - 50.0) * kDeg);
        }
    // Crane up (and back) from the shooter's view.
    for (double up : {0.25, 0.5, 0.85})
      for (double back : {0.0, 0.4}) {
        const Vec3 location = previous + Vec3(0, 0, up) - back * aim;
        add_look(location, (Vec3(location.x(), location.y(), 0) - Vec3(middle.x(), middle.y(), 0)).norm() +
                               0.5 * (location - previous).norm());
      }
    // Walk beside a slow ball: behind it, a little to the side the camera is on, and above.
    if (peak_speed_[static_cast<std::size_t>(subject)] < 0.8 * kPlanSpeed) {
      for (double s : {wanted == 0 ? 1.0 : wanted, wanted == 0 ? -1.0 : wanted})
        for (const Vec3& offset : {Vec3(-0.7, 0.35 * s, 0.45), Vec3(-0.95, 0.45 * s, 0.65)}) {
          CameraShot f;
          f.mode = CameraMode::follow;
          f.ball = subject;
          f.location = mm(offset);
          options.push_back({0.9 + 0.1 * offset.norm(), f});
        }
    }
    std::stable_sort(options.begin(), options.end(), [](const Option& x, const Option& y) { return x.cost < y.cost; });
    std::vector<CameraShot> candidates;
    for (const Option& o : options) candidates.push_back(o.shot);
    // Usually the blend starts as the stick strikes; when the camera would have to hurry after a fast
    // ball, it starts a little earlier, while the ball still rests, and arrives soon after the key...
    std::vector<Timing> usual, early;
    for (double post : {0.35, 0.5, 0.65, 0.8, 0.95}) usual.push_back({shots[1].pre, post});
    // ... but never before the stick's forward stroke, so that the strike is always seen from behind.
    const double early_pre = hundredths(std::min(0.9, (t0 - (cue_time - 0.1)) / t0));
    if (early_pre > shots[1].pre)
      for (double post : {0.1, 0.2, 0.35}) early.push_back({early_pre, post});
    if (const std::optional<CameraShot> chosen = choose_timed(shots, lines, 1, candidates, usual, early, t1)) {
      shots[1] = *chosen;
      for (std::size_t k = 2; k < shots.size(); ++k) {
        const CameraKey key = shots[k].key;
        shots[k] = shots[1];
        shots[k].key = key;
        shots[k].pre = 0;
        shots[k].post = 0;
      }
    } else {
      // Nothing fits: the shooter's view holds until the wide shot (or to the end).
      shots.erase(shots.begin() + 1);
      lines.erase(lines.begin() + 1);
      subjects.erase(subjects.begin() + 1);
      for (std::size_t k = 1; k < shots.size(); ++k) {
        const CameraKey key = shots[k].key;
        shots[k] = shots[0];
        shots[k].key = key;
      }
    }
  }

  // 3. Wide: the whole table from where the camera is, as the balls settle.
  const int last = static_cast<int>(shots.size()) - 1;
  const auto w = static_cast<std::size_t>(last);
  if (wide_key && last >= 1 && same_camera_key(shots[w].key, wide_key->key)) {
    const double t0 = *wide_time;
    const double since = t0 - (last >= 2 ? *subject_time : 0.0);
    const TableRect n = layout_.noses;
    const Vec3 centre(mm(0.5 * (n.x0 + n.x1)), mm(0.5 * (n.y0 + n.y1)), 0);
    // The cloth to its cushions' noses, whole.
    const std::vector<Vec3> corners = {Vec3(n.x0, n.y0, 0), Vec3(n.x1, n.y0, 0), Vec3(n.x0, n.y1, 0),
                                       Vec3(n.x1, n.y1, 0)};
    Scene copy = scene_;
    copy.camera = shots;
    std::vector<Diagnostic> ignored;
    const std::optional<CameraScript> so_far = CameraScript::build(copy, timeline_, ignored);
    const Vec3 previous = so_far ? so_far->pose(t0).location : shots[w - 1].location;
    const LineOfAction& line = lines[w];
    const double wanted = side_to_keep(line, previous);
    struct Option {
      double cost = 0;
      CameraShot shot;
    };
    std::vector<Option> options;
    for (double elevation : {50.0, 42.0, 35.0, 28.0})
      for (int a = 0; a < 12; ++a) {
        const double azimuth = a * 30.0 * kDeg;
        const Vec3 direction(std::cos(elevation * kDeg) * std::cos(azimuth),
                             std::cos(elevation * kDeg) * std::sin(azimuth), std::sin(elevation * kDeg));
        for (double distance = 2.4; distance <= 5.0; distance += 0.2) {
          CameraShot s;
          s.mode = CameraMode::hover;
          s.location = mm(centre + distance * direction);
          s.target = centre;
          const CameraPose pose{s.location, s.target, false};
          if (!std::all_of(corners.begin(), corners.end(), [&](const Vec3& p) { return in_picture(pose, p, 0.01); }))
            continue;
          if (clear(s.location, -1) && keeps_side(line, wanted, s.location))
            options.push_back({(s.location - previous).norm() + 0.3 * distance, s});
          break;
        }
      }
    std::stable_sort(options.begin(), options.end(), [](const Option& x, const Option& y) { return x.cost < y.cost; });
    std::vector<CameraShot> candidates;
    for (const Option& o : options) candidates.push_back(o.shot);
    std::vector<Timing> usual, early;
    for (double post : {0.35, 0.5, 0.65, 0.8, 0.95}) usual.push_back({0.0, post});
    for (double lead : {0.4, 0.8})
      for (double post : {0.35, 0.65, 0.95}) early.push_back({hundredths(std::min(0.5, lead / since)), post});
    if (const std::optional<CameraShot> chosen = choose_timed(shots, lines, last, candidates, usual, early, duration)) {
      shots[w] = *chosen;
    } else {
      shots.resize(w);
      lines.resize(w);
      subjects.resize(w);
    }
  }

  DirectedCamera out;
  out.shots = shots;
  out.lines = lines;
  out.subjects = subjects;
  for (std::size_t k = 0; k < shots.size(); ++k) {
    const CameraShot& s = shots[k];
    std::string comment;
    if (k == 0) {
      comment = "the approach and the stroke from behind and above " + ball_name(scene_, c);
      if (first_object >= 0) comment += ", into " + ball_name(scene_, first_object);
    } else if (s.mode != CameraMode::hover) {
      const bool drops = std::isfinite(drop_time_[static_cast<std::size_t>(subject)]);
      const std::string what = drops ? "" : (subject == c ? "" : ", the fastest ball,");
      comment = (s.mode == CameraMode::follow ? "walk behind " : "watch ") + ball_name(scene_, subject) + what +
                (drops ? " into its pocket" : " on its run");
    } else {
      comment = "wide: the whole table as the balls settle";
    }
    out.comments.push_back(comment);
  }
  return out;
}

void append_vector(std::string& out, const Vec3& v) {
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    append_number(out, v[i]);
  }
}

}  // namespace

double LineOfAction::side(const Vec3& p) const {
  return direction.x() * (p.y() - point.y()) - direction.y() * (p.x() - point.x());
}

bool in_picture(const CameraPose& pose, const Vec3& point, double margin) {
  return CameraView(pose).contains(point, margin);
}

DirectedCamera direct_camera(const Scene& scene, const Timeline& timeline) {
  if (scene.balls.empty() || timeline.events().empty()) {
    DirectedCamera out;
    CameraShot shot = CameraScript::default_shot(scene);
    shot.key.kind = CameraKeyKind::start;
    shot.location = mm(shot.location);
    shot.target = mm(shot.target);
    out.shots.push_back(shot);
    out.comments.push_back("wide: the whole table");
    out.lines.push_back({});
    out.subjects.push_back(-1);
    return out;
  }
  return Director(scene, timeline).run();
}

std::string camera_script_text(const DirectedCamera& camera, const std::string& scene_name) {
  std::string out = "camera\n";
  out += "# Written by the automatic director for " + scene_name +
         ". Each line starts at a moment named by what\n"
         "# happens, so it stays on its moment when the shot changes; edit the numbers to taste.\n";
  for (std::size_t k = 0; k < camera.shots.size(); ++k) {
    const CameraShot& s = camera.shots[k];
    std::string line = "event " + camera_key_text(s.key, s.event) + " ";
    append_number(line, s.pre);
    line += ' ';
    append_number(line, s.post);
    switch (s.mode) {
      case CameraMode::hover:
        line += " hover";
        append_vector(line, s.location);
        line += ' ';
        append_vector(line, s.target);
        break;
      case CameraMode::look:
        line += " look";
        append_vector(line, s.location);
        line += "  " + std::to_string(s.ball);
        break;
      case CameraMode::follow:
        line += " follow " + std::to_string(s.ball) + " ";
        append_vector(line, s.location);
        break;
    }
    out += line + "   # " + (k < camera.comments.size() ? camera.comments[k] : std::string()) + "\n";
  }
  out += "endcamera\n";
  return out;
}

}  // namespace bsim
