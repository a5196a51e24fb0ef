#include "director.h"

// How the director shoots. Televised pool is covered in three beats, and the director writes one
// description for each:
//   1. the approach and the stroke from behind and above the cue ball, down the line of aim (the
//      "shooter's view" of broadcast pool), held until the cue ball meets its first object ball;
//   2. the ball that matters (the last object ball pocketed; else the cue ball if it is pocketed;
//      else the object ball that last met a pocket's jaw; else the fastest object ball) on its run to
//      the pocket, with a `look` from a high place (or a `follow` when the ball is slow enough to walk
//      beside), keyed at the contact that sets it going;
//   3. a wide shot of the whole table as the balls settle, from the moment it drops (else from its
//      last contact: a rattle in a pocket's jaws is watched to its last knock before the camera goes wide).
// Film grammar it keeps:
//   - the 180-degree rule: the camera stays on one side of the line of action (here the subject's
//     path at each description's key) from one description to the next (D. Arijon, "Grammar of the
//     Film Language", 1976, ch. 2; J. V. Mascelli, "The Five C's of Cinematography", 1965,
//     "Continuity": the action axis). A camera on the line itself (the shooter's view) is neutral
//     and may go to either side;
//   - a shot holds long enough to be read: no description spans less than kMinDescriptionSeconds
//     (R. Thompson and C. J. Bowen, "Grammar of the Edit", 2009: a shot needs time for the viewer to
//     take in its content);
//   - one camera, carried: every change within a shot is a blend (no cut), the camera never moves
//     faster than a person walks with it (kCameraCarrySpeed), keeps room around the balls and stays
//     above the table, below the ceiling and out of the lamp.
// Each placement is chosen from a fixed, ordered list of candidates by simulating the real camera
// (CameraScript::pose) over the shot: the first that keeps every pocketed ball and the cue ball in
// the picture long enough and breaks no rule wins, so the result is deterministic.
// The beats below propose the candidates; director_judge.cpp holds the rules and the judge that
// films and scores them.
// A scene of several shots is filmed shot by shot, each as one (its keys counting within it: `shot K
// cue`), over its stretch of the timeline from its start to the next shot's; between shots the camera
// cuts to the next shooter's view, as broadcast pool cuts between shots (within a shot it only blends).

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "camera_interpolation.h"
#include "camera_key.h"
#include "camera_view.h"
#include "director_judge.h"
#include "number_format.h"
#include "table.h"

namespace bsim {

using directing::clear_of_room;
using directing::hold_after;
using directing::Judge;
using directing::keeps_side;
using directing::kPlanMargin;
using directing::kPlanSpeed;
using directing::ShotSamples;
using directing::side_to_keep;
using directing::Timings;
using directing::Verdict;

namespace {

/// Hz at which a candidate script is sampled (speed, clearance, what is in the picture).
constexpr double kGridHz = 120.0;
/// m/s below which a ball counts as at rest.
constexpr double kMovingSpeed = 1e-3;

double mm(double v) { return std::round(v * 1000.0) / 1000.0; }
double hundredths(double v) { return std::round(v * 100.0) / 100.0; }
Vec3 mm(const Vec3& v) { return Vec3(mm(v.x()), mm(v.y()), mm(v.z())); }

Vec3 horizontal_unit(const Vec3& v, const Vec3& fallback) {
  const Vec3 h(v.x(), v.y(), 0);
  return h.norm() > 1e-9 ? Vec3(h / h.norm()) : fallback;
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

/// One stroke as the director films it: the cue ball, the way it is sent, and the span of time its
/// descriptions cover. A scene has one per shot, each over its shot's stretch of the timeline, and
/// the beats below run once for each.
struct Stroke {
  int shot = 0;           ///< from 0 (Scene::cues, Timeline::shots())
  int key_shot = -1;      ///< what its keys count within: `shot`, or -1 (the whole scene) in a scene of one shot
  double begin = 0;       ///< s, its first description's key
  double end = 0;         ///< s, where its last description ends
  double cue_time = 0;    ///< s, the stick strikes
  int cue_ball = 0;       ///< file-order index
  Vec3 cue_at{0, 0, 0};   ///< m, where the cue ball rests before the stroke
  Vec3 aim{1, 0, 0};      ///< unit, horizontal: the line of aim
  int first_object = -1;  ///< the cue ball's first object ball, -1 when it meets none
  Vec3 first_object_at{0, 0, 0};  ///< m, where that ball rests before the stroke
};

/// A key a description starts at, and the instant it resolves to.
struct Moment {
  CameraShot key;
  double time = 0;  ///< s
};

/// The keys of a stroke's beats after the first (which is keyed at the stroke's begin).
struct Plan {
  int subject = -1;            ///< the ball that matters
  std::optional<Moment> ball;  ///< beat 2: none when it would span less than kMinDescriptionSeconds
  std::optional<Moment> wide;  ///< beat 3: none when there is no room for it
};

/// The script as it is written: its descriptions so far, in order, each with its key's instant. A
/// description not yet placed holds the camera of the one before it (hold_after()).
struct Draft {
  DirectedCamera camera;
  std::vector<double> times;  ///< s, per description: its key's instant

  void add(const CameraShot& key, double time, const LineOfAction& line, int subject) {
    camera.shots.push_back(key);
    camera.comments.emplace_back();
    camera.lines.push_back(line);
    camera.subjects.push_back(subject);
    times.push_back(time);
  }
  void erase(std::size_t k) {
    const auto i = static_cast<std::ptrdiff_t>(k);
    camera.shots.erase(camera.shots.begin() + i);
    camera.comments.erase(camera.comments.begin() + i);
    camera.lines.erase(camera.lines.begin() + i);
    camera.subjects.erase(camera.subjects.begin() + i);
    times.erase(times.begin() + i);
  }
  /// s, the key of the description after `k`, or `end` when `k` is the last.
  double next_time(std::size_t k, double end) const { return k + 1 < times.size() ? times[k + 1] : end; }
};

/// The shot sampled at kGridHz for the judge and the beats.
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

/// The ball that matters in shot `shot`: the last object ball pocketed, else the cue ball if it drops,
/// else the object ball that last met a pocket's jaw (it rattled out, or glanced off a jaw point: the
/// near miss is the shot's story), else the fastest object ball, else the cue ball.
int ball_that_matters(const Timeline& timeline, const ShotSamples& samples, int shot, int cue_ball) {
  const std::vector<double>& drop_time = samples.drop_time[static_cast<std::size_t>(shot)];
  const std::vector<double>& peak_speed = samples.peak_speed[static_cast<std::size_t>(shot)];
  int subject = -1;
  double last_drop = -1;
  for (const PocketDrop& d : timeline.pocket_drops())
    if (d.ball != cue_ball && timeline.shot_at(d.time) == shot && d.time > last_drop) {
      last_drop = d.time;
      subject = d.ball;
    }
  if (subject < 0 && std::isfinite(drop_time[static_cast<std::size_t>(cue_ball)])) subject = cue_ball;
  if (subject < 0)
    for (const Event& e : timeline.events())  // in time order: the last one's ball stays
      if (e.type == EventType::ball_jaw && e.shot == shot && !e.balls.empty() && e.balls[0] != cue_ball)
        subject = e.balls[0];
  if (subject < 0) {
    double fastest = 0.05;
    for (int b = 0; b < timeline.ball_count(); ++b)
      if (b != cue_ball && peak_speed[static_cast<std::size_t>(b)] > fastest) {
        fastest = peak_speed[static_cast<std::size_t>(b)];
        subject = b;
      }
  }
  if (subject < 0) subject = cue_ball;
  return subject;
}

/// A candidate place with what it costs (lower first).
struct Costed {
  double cost = 0;
  CameraShot shot;
};

/// The places, cheapest first (ties in the order they were proposed).
std::vector<CameraShot> cheapest_first(std::vector<Costed> options) {
  std::stable_sort(options.begin(), options.end(), [](const Costed& x, const Costed& y) { return x.cost < y.cost; });
  std::vector<CameraShot> places;
  for (const Costed& o : options) places.push_back(o.shot);
  return places;
}

// The three beats. Each proposes its places in the order they are tried (and, for the blends into
// beats 2 and 3, its timings); the judge (director_judge.h) picks among them.

/// Beat 1, the approach and the stroke: hovers behind and above the cue ball, looking down the line of
/// aim at a point between it and its first object ball; the nearest and lowest first, those clear of
/// the room only.
std::vector<CameraShot> stroke_places(const Stroke& stroke, double radius, const TableLayout& layout) {
  const Vec3& c0 = stroke.cue_at;
  const Vec3& aim = stroke.aim;
  const double reach =
      stroke.first_object >= 0 ? std::clamp(0.45 * (stroke.first_object_at - c0).norm(), 0.2, 0.7) : 0.4;
  const Vec3 stroke_target = mm(Vec3(c0.x() + reach * aim.x(), c0.y() + reach * aim.y(), radius));
  std::vector<CameraShot> places;
  for (double back : {0.8, 1.0, 1.25, 1.6, 2.0})
    for (double up : {0.45, 0.6, 0.8, 1.0}) {
      CameraShot s;
      s.mode = CameraMode::hover;
      s.location = mm(c0 - back * aim + Vec3(0, 0, up));
      s.target = stroke_target;
      if (clear_of_room(layout, s.location)) places.push_back(s);
    }
  return places;
}

/// Beat 2, the ball that matters (`subject`) on its run, about `middle`: `look`s from high places
/// around it, cranes up from the camera before it (at `previous`), and `follow`s beside a ball slow
/// enough to walk with (its fastest: `peak_speed`); the closest framing and the shortest walk first,
/// those clear of the room and on the side of `line` the camera before stands on only.
std::vector<CameraShot> ball_places(int subject, const Vec3& middle, double peak_speed, const Vec3& previous,
                                    const LineOfAction& line, const Vec3& aim, const TableLayout& layout) {
  const double wanted = side_to_keep(line, previous);
  std::vector<Costed> options;
  const auto add_look = [&](const Vec3& location, double cost) {
    const Vec3 p = mm(location);
    if (!clear_of_room(layout, p) || !keeps_side(line, wanted, p)) return;
    CameraShot s;
    s.mode = CameraMode::look;
    s.location = p;
    s.ball = subject;
    options.push_back({cost, s});
  };
  for (double distance : {1.0, 1.4, 1.9, 2.5, 3.2})
    for (double elevation : {50.0, 38.0, 62.0})
      for (int a = 0; a < 24; ++a) {
        const double azimuth = a * 15.0 * kDegToRad;
        const Vec3 location = middle + distance * Vec3(std::cos(azimuth), std::sin(azimuth), 0) +
                              Vec3(0, 0, distance * std::tan(elevation * kDegToRad));
        add_look(location,
                 distance + 0.5 * (location - previous).norm() + 0.8 * std::abs(elevation - 50.0) * kDegToRad);
      }
  // Crane up (and back) from the shooter's view.
  for (double up : {0.25, 0.5, 0.85})
    for (double back : {0.0, 0.4}) {
      const Vec3 location = previous + Vec3(0, 0, up) - back * aim;
      add_look(location, (Vec3(location.x(), location.y(), 0) - Vec3(middle.x(), middle.y(), 0)).norm() +
                             0.5 * (location - previous).norm());
    }
  // Walk beside a slow ball: behind it, a little to the side the camera is on, and above.
  if (peak_speed < 0.8 * kPlanSpeed) {
    for (double s : {wanted == 0 ? 1.0 : wanted, wanted == 0 ? -1.0 : wanted})
      for (const Vec3& offset : {Vec3(-0.7, 0.35 * s, 0.45), Vec3(-0.95, 0.45 * s, 0.65)}) {
        CameraShot f;
        f.mode = CameraMode::follow;
        f.ball = subject;
        f.location = mm(offset);
        options.push_back({0.9 + 0.1 * offset.norm(), f});
      }
  }
  return cheapest_first(std::move(options));
}

/// Beat 2's blends, for its key at `key_time` after the one before it at `previous_time`.
Timings ball_timings(double key_time, double previous_time, double cue_time) {
  const double span = key_time - previous_time;
  // The blend starts as the stick strikes (or at most 0.3 s before the key), never during the approach.
  const double start = std::max(cue_time, key_time - 0.3);
  const double pre = span > 0 ? hundredths(std::max(0.0, (key_time - start) / span)) : 0.0;
  // Usually the blend starts as the stick strikes; when the camera would have to hurry after a fast
  // ball, it starts a little earlier, while the ball still rests, and arrives soon after the key...
  Timings timings;
  for (double post : {0.35, 0.5, 0.65, 0.8, 0.95}) timings.usual.push_back({pre, post});
  // ... but never before the stick's forward stroke, so that the strike is always seen from behind.
  const double early_pre = hundredths(std::min(0.9, (key_time - (cue_time - 0.1)) / span));
  if (early_pre > pre)
    for (double post : {0.1, 0.2, 0.35}) timings.early.push_back({early_pre, post});
  return timings;
}

/// Beat 3, wide: hovers that frame the whole cloth from the room around it, for each direction the
/// nearest that does; the shortest walk from the camera before it (at `previous`) first, those clear
/// of the room and on the side of `line` it stands on only.
std::vector<CameraShot> wide_places(const TableLayout& layout, const Vec3& previous, const LineOfAction& line) {
  const TableRect n = layout.noses;
  const Vec3 centre(mm(0.5 * (n.x0 + n.x1)), mm(0.5 * (n.y0 + n.y1)), 0);
  // The cloth to its cushions' noses, whole.
  const std::vector<Vec3> corners = {Vec3(n.x0, n.y0, 0), Vec3(n.x1, n.y0, 0), Vec3(n.x0, n.y1, 0),
                                     Vec3(n.x1, n.y1, 0)};
  const double wanted = side_to_keep(line, previous);
  std::vector<Costed> options;
  for (double elevation : {50.0, 42.0, 35.0, 28.0})
    for (int a = 0; a < 12; ++a) {
      const double azimuth = a * 30.0 * kDegToRad;
      const Vec3 direction(std::cos(elevation * kDegToRad) * std::cos(azimuth),
                           std::cos(elevation * kDegToRad) * std::sin(azimuth), std::sin(elevation * kDegToRad));
      for (double distance = 2.4; distance <= 5.0; distance += 0.2) {
        CameraShot s;
        s.mode = CameraMode::hover;
        s.location = mm(centre + distance * direction);
        s.target = centre;
        const CameraPose pose{s.location, s.target, false};
        if (!std::all_of(corners.begin(), corners.end(),
                         [&](const Vec3& p) { return CameraView(pose).contains(p, 0.01); }))
          continue;
        if (clear_of_room(layout, s.location) && keeps_side(line, wanted, s.location))
          options.push_back({(s.location - previous).norm() + 0.3 * distance, s});
        break;
      }
    }
  return cheapest_first(std::move(options));
}

/// Beat 3's blends, for its key `since` s after the one before it: from its key, or up to 0.8 s
/// before it.
Timings wide_timings(double since) {
  Timings timings;
  for (double post : {0.35, 0.5, 0.65, 0.8, 0.95}) timings.usual.push_back({0.0, post});
  for (double lead : {0.4, 0.8})
    for (double post : {0.35, 0.65, 0.95}) timings.early.push_back({hundredths(std::min(0.5, lead / since)), post});
  return timings;
}

class Director {
 public:
  Director(const Scene& scene, const Timeline& timeline)
      : scene_(scene),
        timeline_(timeline),
        layout_(table_layout(scene)),
        radius_(scene.physics.ball_radius),
        samples_(sample_shot(timeline, radius_)) {
    for (int k = 0; k < std::max(1, timeline.shot_count()); ++k) {
      const int cue_ball = scene.cues[std::min(static_cast<std::size_t>(k), scene.cues.size() - 1)].target;
      judges_.emplace_back(scene, timeline, samples_, k, ball_that_matters(timeline, samples_, k, cue_ball));
    }
  }

  DirectedCamera run();

 private:
  struct Contact {
    double time = 0;
    int other = -1;
  };

  Vec3 at(int ball, double t) const { return timeline_.motion_state(ball, t).position; }
  Vec3 heading(int ball, double t, const Vec3& fallback) const {
    return horizontal_unit(timeline_.motion_state(ball, t).velocity, fallback);
  }

  /// Every contact of `ball` with another ball in the stroke's shot, in time order (a contact inside a
  /// group counting).
  std::vector<Contact> contacts(int ball, const Stroke& stroke) const {
    std::vector<Contact> found;
    for (const Event& e : timeline_.events()) {
      if (e.type != EventType::ball_ball || e.shot != stroke.shot) continue;
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

  /// A key that counts within the stroke's shot (in a scene of several).
  static CameraShot key_in(const Stroke& stroke, CameraKeyKind kind, int a = -1, int b = -1, int ordinal = 1,
                           double seconds = 0) {
    CameraShot shot = keyed(kind, a, b, ordinal, seconds);
    shot.key.shot = stroke.key_shot;
    return shot;
  }
  /// s, when `ball` first drops in the stroke's shot (infinity if it does not).
  double drop_time(int ball, const Stroke& stroke) const {
    return samples_.drop_time[static_cast<std::size_t>(stroke.shot)][static_cast<std::size_t>(ball)];
  }
  const Judge& judge(const Stroke& stroke) const { return judges_[static_cast<std::size_t>(stroke.shot)]; }

  /// How `ball` last met a pocket's jaws in the stroke's shot, for a comment: " rattling in the jaws of
  /// the top-right corner (pocket 2)" (two knocks or more there), " off a jaw of ..." (one); "" if never.
  std::string jaw_story(int ball, const Stroke& stroke) const {
    int pocket = -1, knocks = 0;
    for (const Event& e : timeline_.events())
      if (e.type == EventType::ball_jaw && e.shot == stroke.shot && !e.balls.empty() && e.balls[0] == ball) {
        knocks = e.pocket == pocket ? knocks + 1 : 1;
        pocket = e.pocket;
      }
    if (pocket < 0) return "";
    return (knocks > 1 ? " rattling in the jaws of " : " off a jaw of ") + pocket_name(scene_.pockets, pocket);
  }
  /// Shot `shot`'s stroke, over its stretch of the timeline.
  Stroke stroke_of(int shot) const;
  /// The keys of the stroke's beats.
  Plan plan_beats(const Stroke& stroke) const;
  /// Beat 2's key: the contact that first sets `subject` going (or the strike, for the cue ball).
  std::optional<Moment> set_going(int subject, const Stroke& stroke) const;
  /// Beat 3's key, at least kMinDescriptionSeconds after `after` and before the stroke's end.
  std::optional<Moment> settle(int subject, double after, const Stroke& stroke) const;
  /// Adds the stroke's descriptions to `draft` and places them, beat by beat.
  void film(const Stroke& stroke, Draft& draft) const;
  /// Each places description `slot` of `draft` (its key written), or leaves it out when no place fits;
  /// the descriptions after it hold its camera.
  void place_stroke(Draft& draft, std::size_t slot, const Stroke& stroke) const;
  bool place_ball(Draft& draft, std::size_t slot, const Stroke& stroke) const;
  void place_wide(Draft& draft, std::size_t slot, const Stroke& stroke) const;

  const Scene& scene_;
  const Timeline& timeline_;
  TableLayout layout_;
  double radius_ = 0;
  ShotSamples samples_;
  std::vector<Judge> judges_;  ///< per shot
};

Stroke Director::stroke_of(int shot) const {
  const std::vector<ShotSpan>& spans = timeline_.shots();
  const auto k = static_cast<std::size_t>(shot);
  const bool several = spans.size() > 1;
  Stroke stroke;
  stroke.shot = shot;
  stroke.key_shot = several ? shot : -1;
  stroke.begin = several ? spans[k].start : 0.0;
  stroke.end = several && k + 1 < spans.size() ? spans[k + 1].start : timeline_.duration();
  stroke.cue_time = several ? spans[k].cue : timeline_.cue_time();
  const Cue& cue = scene_.cues[std::min(k, scene_.cues.size() - 1)];
  stroke.cue_ball = cue.target;
  // The first shot from the scene's own balls; a later one from where the shots before left them.
  const Ball& ball = scene_.balls[static_cast<std::size_t>(stroke.cue_ball)];
  const auto rests = [&](int b) {
    return shot == 0 ? scene_.balls[static_cast<std::size_t>(b)].position : at(b, stroke.cue_time);
  };
  stroke.cue_at = rests(stroke.cue_ball);
  const double heading_rad = cue.heading_deg * kDegToRad;
  stroke.aim =
      horizontal_unit(shot == 0 ? ball.velocity : Vec3(0, 0, 0), Vec3(std::cos(heading_rad), std::sin(heading_rad), 0));
  // The cue ball's first object ball.
  const std::vector<Contact> cue_contacts = contacts(stroke.cue_ball, stroke);
  stroke.first_object = cue_contacts.empty() ? -1 : cue_contacts.front().other;
  if (stroke.first_object >= 0) stroke.first_object_at = rests(stroke.first_object);
  return stroke;
}

Plan Director::plan_beats(const Stroke& stroke) const {
  Plan plan;
  plan.subject = ball_that_matters(timeline_, samples_, stroke.shot, stroke.cue_ball);
  const std::optional<Moment> going = set_going(plan.subject, stroke);
  if (!going || stroke.end - going->time < kMinDescriptionSeconds) return plan;
  plan.ball = going;
  plan.wide = settle(plan.subject, going->time, stroke);
  return plan;
}

std::optional<Moment> Director::set_going(int subject, const Stroke& stroke) const {
  CameraShot key = key_in(stroke, CameraKeyKind::cue);
  const std::vector<Contact> subject_contacts = contacts(subject, stroke);
  if (subject != stroke.cue_ball && !subject_contacts.empty())
    key = key_in(stroke, CameraKeyKind::hit, subject_contacts.front().other, subject);
  std::optional<double> time = resolve(key);
  if (!time) {
    key = key_in(stroke, CameraKeyKind::cue);
    time = resolve(key);
  }
  if (!time) return std::nullopt;
  return Moment{key, *time};
}

std::optional<Moment> Director::settle(int subject, double after, const Stroke& stroke) const {
  // From the subject's drop, else its last contact (a cushion, a pocket's jaw: a rattle is watched to
  // its end), else a time as it slows.
  if (stroke.end - after < 2 * kMinDescriptionSeconds) return std::nullopt;
  const double earliest = after + kMinDescriptionSeconds, latest = stroke.end - kMinDescriptionSeconds;
  std::vector<CameraShot> options;
  if (std::isfinite(drop_time(subject, stroke))) options.push_back(key_in(stroke, CameraKeyKind::drop, subject));
  double last_contact = -1;
  CameraShot last_key;
  for (const Event& e : timeline_.events()) {
    const bool rail = e.type == EventType::ball_rail, jaw = e.type == EventType::ball_jaw;
    if ((rail || jaw) && e.shot == stroke.shot && !e.balls.empty() && e.balls[0] == subject && e.time > last_contact) {
      last_contact = e.time;
      last_key = key_in(stroke, jaw ? CameraKeyKind::jaw : CameraKeyKind::cushion, subject, -1, CameraKey::kLast);
    }
  }
  const std::vector<Contact> subject_contacts = contacts(subject, stroke);
  if (!subject_contacts.empty() && subject_contacts.back().time > last_contact)
    last_key = key_in(stroke, CameraKeyKind::hit, subject_contacts.back().other, subject, CameraKey::kLast);
  if (last_contact >= 0 || !subject_contacts.empty()) options.push_back(last_key);
  for (const CameraShot& option : options) {
    const std::optional<double> t = resolve(option);
    if (t && *t >= earliest && *t <= latest) return Moment{option, *t};
  }
  // As the subject slows below a walking pace, within the bounds.
  double slow = earliest;
  for (const double t : samples_.times)
    if (t >= earliest) {
      slow = t;
      const Vec3 v = timeline_.motion_state(subject, t).velocity;
      if (Vec3(v.x(), v.y(), 0).norm() < 0.3) break;
    }
  // Its seconds count from the start of the stroke's shot (of the scene, for a scene of one).
  const double seconds = std::ceil((std::clamp(slow, earliest, latest) - stroke.begin) * 100.0) / 100.0;
  if (stroke.begin + seconds > latest) return std::nullopt;
  const CameraShot key = key_in(stroke, CameraKeyKind::at, -1, -1, 1, seconds);
  const std::optional<double> time = resolve(key);
  if (!time) return std::nullopt;
  return Moment{key, *time};
}

void Director::film(const Stroke& stroke, Draft& draft) const {
  const Plan plan = plan_beats(stroke);
  const int subject = plan.subject;
  // The keys and their lines of action.
  const std::size_t first = draft.times.size();
  draft.add(key_in(stroke, CameraKeyKind::start), stroke.begin, {stroke.cue_at, stroke.aim}, stroke.cue_ball);
  if (plan.ball) {
    const double after = std::min(plan.ball->time + 1e-6, stroke.end);
    draft.add(plan.ball->key, plan.ball->time, {at(subject, plan.ball->time), heading(subject, after, stroke.aim)},
              subject);
  }
  if (plan.wide) {
    const double before = std::max(plan.wide->time - 1e-6, stroke.begin);
    draft.add(plan.wide->key, plan.wide->time,
              {at(subject, before), heading(subject, before, draft.camera.lines.back().direction)}, subject);
  }
  // The next shot's start ends this shot's last blend (a blend's `post` is a share of the time to the
  // next key): its description stands in, holding this shot's camera, until that shot is filmed.
  const bool closed = stroke.key_shot >= 0 && stroke.shot + 1 < timeline_.shot_count();
  if (closed) {
    CameraShot next_start = key_in(stroke, CameraKeyKind::start);
    next_start.key.shot = stroke.key_shot + 1;
    draft.add(next_start, stroke.end, draft.camera.lines.back(), draft.camera.subjects.back());
  }
  // The beats in turn, each placed with the ones before it fixed.
  place_stroke(draft, first, stroke);
  std::size_t next = first + 1;
  if (plan.ball && place_ball(draft, next, stroke)) ++next;
  if (plan.wide) place_wide(draft, next, stroke);
  if (closed) draft.erase(draft.times.size() - 1);
}

void Director::place_stroke(Draft& draft, std::size_t slot, const Stroke& stroke) const {
  std::vector<CameraShot>& shots = draft.camera.shots;
  // Filmed alone (with the descriptions before it) until the next key.
  const double until = draft.next_time(slot, stroke.end);
  const std::vector<LineOfAction> lines(draft.camera.lines.begin(),
                                        draft.camera.lines.begin() + static_cast<std::ptrdiff_t>(slot) + 1);
  std::vector<CameraShot> trial(shots.begin(), shots.begin() + static_cast<std::ptrdiff_t>(slot) + 1);
  bool placed = false;
  for (const CameraShot& option : stroke_places(stroke, radius_, layout_)) {
    trial[slot].mode = option.mode;
    trial[slot].location = option.location;
    trial[slot].target = option.target;
    const Verdict v = judge(stroke).evaluate(trial, lines, until);
    CameraPose pose{option.location, option.target, false};
    const bool frames = stroke.first_object < 0 || CameraView(pose).contains(stroke.first_object_at, kPlanMargin);
    if (v.ok && frames && CameraView(pose).contains(stroke.cue_at, kPlanMargin)) {
      shots[slot].mode = option.mode;
      shots[slot].location = option.location;
      shots[slot].target = option.target;
      placed = true;
      break;
    }
  }
  if (!placed) {
    const CameraShot fallback = CameraScript::default_shot(scene_);
    shots[slot].mode = fallback.mode;
    shots[slot].location = mm(fallback.location);
    shots[slot].target = mm(fallback.target);
  }
  hold_after(shots, slot);
  std::string& comment = draft.camera.comments[slot];
  comment = "the approach and the stroke from behind and above " + ball_name(scene_, stroke.cue_ball);
  if (stroke.first_object >= 0) comment += ", into " + ball_name(scene_, stroke.first_object);
}

bool Director::place_ball(Draft& draft, std::size_t slot, const Stroke& stroke) const {
  std::vector<CameraShot>& shots = draft.camera.shots;
  const int subject = draft.camera.subjects[slot];
  const auto ball = static_cast<std::size_t>(subject);
  const double t0 = draft.times[slot];
  const double t1 = draft.next_time(slot, stroke.end);
  const Vec3 from = at(subject, t0);
  const Vec3 to = at(subject, std::min(t1, drop_time(subject, stroke)));
  const Vec3 middle = 0.5 * (from + to);
  const std::vector<CameraShot> places =
      ball_places(subject, middle, samples_.peak_speed[static_cast<std::size_t>(stroke.shot)][ball],
                  shots[slot - 1].location, draft.camera.lines[slot], stroke.aim, layout_);
  const Timings timings = ball_timings(t0, draft.times[slot - 1], stroke.cue_time);
  const std::optional<CameraShot> chosen = judge(stroke).choose(shots, draft.camera.lines, slot, places, timings, t1);
  if (!chosen) {
    // Nothing fits: the camera before it holds until the wide shot (or to the end).
    draft.erase(slot);
    hold_after(shots, slot - 1);
    return false;
  }
  shots[slot] = *chosen;
  hold_after(shots, slot);
  const bool drops = std::isfinite(drop_time(subject, stroke));
  const std::string jaws = drops ? "" : jaw_story(subject, stroke);
  const std::string what = drops || !jaws.empty() ? "" : (subject == stroke.cue_ball ? "" : ", the fastest ball,");
  draft.camera.comments[slot] = (chosen->mode == CameraMode::follow ? "walk behind " : "watch ") +
                                ball_name(scene_, subject) + what +
                                (drops          ? " into its pocket"
                                 : jaws.empty() ? " on its run"
                                                : jaws);
  return true;
}

void Director::place_wide(Draft& draft, std::size_t slot, const Stroke& stroke) const {
  std::vector<CameraShot>& shots = draft.camera.shots;
  const double t0 = draft.times[slot];
  const double since = t0 - draft.times[slot - 1];
  // From where the camera is as the beat begins.
  const std::optional<CameraPose> so_far = judge(stroke).pose(shots, t0);
  const Vec3 previous = so_far ? so_far->location : shots[slot - 1].location;
  const std::vector<CameraShot> places = wide_places(layout_, previous, draft.camera.lines[slot]);
  const std::optional<CameraShot> chosen =
      judge(stroke).choose(shots, draft.camera.lines, slot, places, wide_timings(since), stroke.end);
  if (!chosen) {
    draft.erase(slot);
    hold_after(shots, slot - 1);
    return;
  }
  shots[slot] = *chosen;
  hold_after(shots, slot);
  draft.camera.comments[slot] = "wide: the whole table as the balls settle";
}

DirectedCamera Director::run() {
  Draft draft;
  for (int shot = 0; shot < std::max(1, timeline_.shot_count()); ++shot) film(stroke_of(shot), draft);
  return draft.camera;
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
