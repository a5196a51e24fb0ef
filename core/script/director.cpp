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
// The director decides the beats, their moments (named as keys: camera_moment.h) and their order;
// director_candidates.cpp proposes the places for each beat and director_judge.cpp holds the rules
// and the judge that films and scores them.
// A scene of several shots is filmed shot by shot, each as one (its keys counting within it: `shot K
// cue`), over its stretch of the timeline from its start to the next shot's; between shots the camera
// cuts to the next shooter's view, as broadcast pool cuts between shots (within a shot it only blends).

#include <algorithm>
#include <cmath>
#include <optional>

#include "camera_moment.h"
#include "camera_view.h"
#include "cue_geometry.h"
#include "cue_script.h"
#include "director_candidates.h"
#include "director_judge.h"
#include "table.h"

namespace bsim {

using directing::ball_places;
using directing::ball_timings;
using directing::FilmedStroke;
using directing::hold_after;
using directing::Judge;
using directing::kPlanMargin;
using directing::sample_shot;
using directing::ShotSamples;
using directing::stroke_places;
using directing::Timings;
using directing::Verdict;
using directing::wide_places;
using directing::wide_timings;

namespace {

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

/// The share of the picture's width and height the opening keeps round the cloth, and how far back
/// it may stand for that (m from the table's middle).
constexpr double kOpeningMargin = 0.05;
constexpr double kOpeningFarthest = 5.5;

/// m along the stick from its tip to the point that tells which way it runs in the picture.
constexpr double kStrikeSeen = 0.1;

/// The keys of a stroke's beats after the first (which is keyed at the stroke's begin).
struct Plan {
  int subject = -1;                 ///< the ball that matters
  std::optional<NamedMoment> ball;  ///< beat 2: none when it would span less than kMinDescriptionSeconds
  std::optional<NamedMoment> wide;  ///< beat 3: none when there is no room for it
};

/// The script as it is written: its descriptions so far, in order, each with its key's instant. A
/// description not yet placed holds the camera of the one before it (hold_after()).
struct Draft {
  DirectedCamera camera;
  std::vector<double> times;  ///< s, per description: its key's instant

  void add(const CameraKey& key, double time, const LineOfAction& line, int subject) {
    camera.shots.emplace_back().key = key;
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

class Director {
 public:
  Director(const Scene& scene, const Timeline& timeline, const FilmingNotes& notes)
      : scene_(scene),
        timeline_(timeline),
        notes_(notes),
        layout_(table_layout(scene)),
        radius_(scene.physics.ball_radius),
        samples_(sample_shot(timeline, radius_)) {
    for (int k = 0; k < std::max(1, timeline.shot_count()); ++k) {
      const int cue_ball = scene.cues[std::min(static_cast<std::size_t>(k), scene.cues.size() - 1)].target;
      judges_.emplace_back(scene, timeline, samples_, k, subject_of(k, cue_ball));
    }
  }

  DirectedCamera run();

 private:
  Vec3 at(int ball, double t) const { return timeline_.motion_state(ball, t).position; }
  Vec3 heading(int ball, double t, const Vec3& fallback) const {
    return horizontal_unit(timeline_.motion_state(ball, t).velocity, fallback);
  }

  /// A key of the stroke's shot (counting within it in a scene of several).
  CameraKey key_in(const FilmedStroke& stroke, CameraKeyKind kind) const {
    return shot_key(timeline_, stroke.shot, kind);
  }
  /// s, when `ball` first drops in the stroke's shot (infinity if it does not).
  double drop_time(int ball, const FilmedStroke& stroke) const {
    return samples_.drop_time[static_cast<std::size_t>(stroke.shot)][static_cast<std::size_t>(ball)];
  }
  const Judge& judge(const FilmedStroke& stroke) const { return judges_[static_cast<std::size_t>(stroke.shot)]; }

  /// How `ball` last met a pocket's jaws in the stroke's shot, for a comment: " rattling in the jaws of
  /// the top-right corner (pocket 2)" (two knocks or more there), " off a jaw of ..." (one); "" if never.
  std::string jaw_story(int ball, const FilmedStroke& stroke) const {
    int pocket = -1, knocks = 0;
    for (const Event* e : ball_touches(timeline_, EventType::ball_jaw, ball, stroke.shot)) {
      knocks = e->pocket == pocket ? knocks + 1 : 1;
      pocket = e->pocket;
    }
    if (pocket < 0) return "";
    return (knocks > 1 ? " rattling in the jaws of " : " off a jaw of ") + pocket_name(scene_.pockets, pocket);
  }
  /// The ball that matters in shot `shot`: the notes' when they name one, else the physics'.
  int subject_of(int shot, int cue_ball) const {
    const auto k = static_cast<std::size_t>(shot);
    if (k < notes_.subjects.size() && notes_.subjects[k] >= 0 && notes_.subjects[k] < timeline_.ball_count())
      return notes_.subjects[k];
    return ball_that_matters(timeline_, samples_, shot, cue_ball);
  }
  /// Whether the stroke opens on a wide shot of the table (a game's first, with room for it).
  bool opens(const FilmedStroke& stroke) const {
    return notes_.opening && stroke.shot == 0 && stroke.cue_time - stroke.begin >= kOpeningSeconds + 0.8;
  }
  /// Places the opening wide shot in description `slot` (keyed at the stroke's begin); false when no
  /// place fits, and the stroke's description (the next) then starts at the begin in its place.
  bool place_opening(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const;
  /// Shot `shot`'s stroke, over its stretch of the timeline.
  FilmedStroke stroke_of(int shot) const;
  /// The pocket `stroke` is played at (FilmedStroke::pocket): `pot_pocket`, else from the cue ball's
  /// `contacts` in its shot.
  int played_pocket(const FilmedStroke& stroke, int pot_pocket, const std::vector<BallContact>& contacts) const;
  /// Whether the stroke's view from `pose` shows what the stroke is about: the cue ball, its first object
  /// ball and, when `with_pocket`, the pocket it is played at, neither of the last two behind the stick
  /// at address, and the strike: the stick's tip, the stick coming in from below.
  bool shows_stroke(const FilmedStroke& stroke, const CameraPose& pose, bool with_pocket) const;
  /// The keys of the stroke's beats.
  Plan plan_beats(const FilmedStroke& stroke) const;
  /// Beat 2's key: the contact that first sets `subject` going (or the strike, for the cue ball).
  std::optional<NamedMoment> set_going(int subject, const FilmedStroke& stroke) const;
  /// Beat 3's key, at least kMinDescriptionSeconds after `after` and before the stroke's end.
  std::optional<NamedMoment> settle(int subject, double after, const FilmedStroke& stroke) const;
  /// Adds the stroke's descriptions to `draft` and places them, beat by beat.
  void film(const FilmedStroke& stroke, Draft& draft) const;
  /// Each places description `slot` of `draft` (its key written), or leaves it out when no place fits;
  /// the descriptions after it hold its camera.
  void place_stroke(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const;
  bool place_ball(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const;
  void place_wide(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const;

  const Scene& scene_;
  const Timeline& timeline_;
  const FilmingNotes& notes_;
  TableLayout layout_;
  double radius_ = 0;
  ShotSamples samples_;
  std::vector<Judge> judges_;  ///< per shot
};

FilmedStroke Director::stroke_of(int shot) const {
  const auto k = static_cast<std::size_t>(shot);
  const ShotStretch stretch = shot_stretch(timeline_, shot);
  FilmedStroke stroke;
  stroke.shot = shot;
  stroke.begin = stretch.start;
  stroke.end = stretch.end;
  stroke.cue_time = stretch.strike;
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
  const std::vector<BallContact> cue_contacts = ball_contacts(timeline_, shot, stroke.cue_ball);
  stroke.first_object = cue_contacts.empty() ? -1 : cue_contacts.front().other(stroke.cue_ball);
  if (stroke.first_object >= 0) stroke.first_object_at = rests(stroke.first_object);
  stroke.pocket = played_pocket(stroke, cue.aims() ? cue.pot_pocket : -1, cue_contacts);
  if (stroke.pocket >= 0) stroke.pocket_at = scene_.pockets[static_cast<std::size_t>(stroke.pocket)].center;
  return stroke;
}

int Director::played_pocket(const FilmedStroke& stroke, int pot_pocket,
                            const std::vector<BallContact>& contacts) const {
  int pocket = pot_pocket;
  // Else where the first object ball drops in this shot, unless a group collision sent it there.
  const auto grouped = [&](int event) {
    return std::any_of(timeline_.events().begin(), timeline_.events().end(),
                       [&](const Event& e) { return e.index == event && e.grouped; });
  };
  if (pocket < 0 && !contacts.empty() && !grouped(contacts.front().event))
    for (const PocketDrop& drop : timeline_.pocket_drops())
      if (drop.ball == stroke.first_object && timeline_.shot_at(drop.time) == stroke.shot) {
        pocket = drop.pocket;
        break;
      }
  return pocket >= 0 && pocket < static_cast<int>(scene_.pockets.size()) ? pocket : -1;
}

Plan Director::plan_beats(const FilmedStroke& stroke) const {
  Plan plan;
  plan.subject = subject_of(stroke.shot, stroke.cue_ball);
  const std::optional<NamedMoment> going = set_going(plan.subject, stroke);
  if (!going || stroke.end - going->time < kMinDescriptionSeconds) return plan;
  plan.ball = going;
  plan.wide = settle(plan.subject, going->time, stroke);
  return plan;
}

std::optional<NamedMoment> Director::set_going(int subject, const FilmedStroke& stroke) const {
  if (subject != stroke.cue_ball)
    if (std::optional<NamedMoment> hit = first_hit(timeline_, subject, stroke.shot)) return hit;
  const CameraKey cue = key_in(stroke, CameraKeyKind::cue);
  const std::optional<KeyInstant> strike = moment_instant(cue, -1, timeline_);
  if (!strike) return std::nullopt;
  return NamedMoment{cue, strike->time, strike->event};
}

std::optional<NamedMoment> Director::settle(int subject, double after, const FilmedStroke& stroke) const {
  // From the subject's drop, else its last contact (a cushion, a pocket's jaw: a rattle is watched to
  // its end), else a time as it slows.
  if (stroke.end - after < 2 * kMinDescriptionSeconds) return std::nullopt;
  const double earliest = after + kMinDescriptionSeconds, latest = stroke.end - kMinDescriptionSeconds;
  const std::optional<NamedMoment> options[] = {
      std::isfinite(drop_time(subject, stroke)) ? first_drop(timeline_, subject, stroke.shot) : std::nullopt,
      last_contact(timeline_, subject, stroke.shot)};
  for (const std::optional<NamedMoment>& option : options)
    if (option && option->time >= earliest && option->time <= latest) return option;
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
  return name_at(timeline_, stroke.shot, seconds);
}

void Director::film(const FilmedStroke& stroke, Draft& draft) const {
  const Plan plan = plan_beats(stroke);
  const int subject = plan.subject;
  // The keys and their lines of action. A game opens on the whole table, then cuts to the breaker.
  const LineOfAction aim_line{stroke.cue_at, stroke.aim};
  const std::optional<NamedMoment> cut =
      opens(stroke) ? name_at(timeline_, stroke.shot, kOpeningSeconds) : std::nullopt;
  const bool opening = cut.has_value();
  if (opening) draft.add(key_in(stroke, CameraKeyKind::start), stroke.begin, aim_line, stroke.cue_ball);
  const std::size_t first = draft.times.size();
  if (cut)
    draft.add(cut->key, cut->time, aim_line, stroke.cue_ball);
  else
    draft.add(key_in(stroke, CameraKeyKind::start), stroke.begin, aim_line, stroke.cue_ball);
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
  const bool closed = stroke.shot + 1 < timeline_.shot_count();
  if (closed)
    draft.add(shot_key(timeline_, stroke.shot + 1, CameraKeyKind::start), stroke.end, draft.camera.lines.back(),
              draft.camera.subjects.back());
  // The beats in turn, each placed with the ones before it fixed.
  const std::size_t stroke_slot = opening && !place_opening(draft, first - 1, stroke) ? first - 1 : first;
  place_stroke(draft, stroke_slot, stroke);
  std::size_t next = stroke_slot + 1;
  if (plan.ball && place_ball(draft, next, stroke)) ++next;
  if (plan.wide) place_wide(draft, next, stroke);
  if (closed) draft.erase(draft.times.size() - 1);
}

bool Director::shows_stroke(const FilmedStroke& stroke, const CameraPose& pose, bool with_pocket) const {
  const CameraView view(pose);
  const std::optional<CueStroke>& stick = judge(stroke).stroke();
  const std::optional<CuePose> address =
      stick ? std::optional<CuePose>(stroke_pose(*stick, at_ball(*stick).begin)) : std::nullopt;
  // In the picture and not behind the stick.
  const auto shown = [&](const Vec3& p, double margin) {
    return view.contains(p, margin) && !(address && stick_hides(*address, pose, p, radius_));
  };
  if (!view.contains(stroke.cue_at, kPlanMargin)) return false;
  if (stroke.first_object >= 0 && !shown(stroke.first_object_at, kPlanMargin)) return false;
  // The strike is seen: the tip in the picture as the balls are, the stick coming into it from below
  // as a shooter's view shows it (from under a raised stick it would come down over the balls).
  if (address) {
    const std::optional<PicturePoint> tip = view.project(address->tip);
    const std::optional<PicturePoint> back = view.project(address->tip + kStrikeSeen * address->axis);
    if (!view.contains(address->tip, kPlanMargin) || (back && back->y >= tip->y)) return false;
  }
  return !with_pocket || stroke.pocket < 0 || shown(stroke.pocket_at, 0);
}

void Director::place_stroke(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const {
  std::vector<CameraShot>& shots = draft.camera.shots;
  // Filmed alone (with the descriptions before it) until the next key.
  const double until = draft.next_time(slot, stroke.end);
  const std::vector<LineOfAction> lines(draft.camera.lines.begin(),
                                        draft.camera.lines.begin() + static_cast<std::ptrdiff_t>(slot) + 1);
  std::vector<CameraShot> trial(shots.begin(), shots.begin() + static_cast<std::ptrdiff_t>(slot) + 1);
  // The first place that keeps the rules (the stick's share of the picture among them) and shows the
  // cue ball, its first object ball and the pocket it is played at; else the first that misses only
  // the pocket; else the default camera.
  std::optional<CameraShot> chosen, without_pocket;
  for (const CameraShot& option : stroke_places(stroke, radius_, layout_)) {
    trial[slot].mode = option.mode;
    trial[slot].location = option.location;
    trial[slot].target = option.target;
    const CameraPose pose{option.location, option.target, false};
    if (!shows_stroke(stroke, pose, false) || !judge(stroke).evaluate(trial, lines, until).ok) continue;
    if (shows_stroke(stroke, pose, true)) {
      chosen = option;
      break;
    }
    if (!without_pocket) without_pocket = option;
  }
  if (!chosen) chosen = without_pocket;
  if (!chosen) {
    chosen = CameraScript::default_shot(scene_);
    chosen->location = to_millimetre(chosen->location);
    chosen->target = to_millimetre(chosen->target);
  }
  shots[slot].mode = chosen->mode;
  shots[slot].location = chosen->location;
  shots[slot].target = chosen->target;
  hold_after(shots, slot);
  std::string& comment = draft.camera.comments[slot];
  comment = "the approach and the stroke from behind and above " + ball_name(scene_, stroke.cue_ball);
  if (stroke.first_object >= 0) comment += ", into " + ball_name(scene_, stroke.first_object);
}

bool Director::place_ball(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const {
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

void Director::place_wide(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const {
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

bool Director::place_opening(Draft& draft, std::size_t slot, const FilmedStroke& stroke) const {
  std::vector<CameraShot>& shots = draft.camera.shots;
  const double until = draft.next_time(slot, stroke.end);
  const std::vector<LineOfAction> lines(draft.camera.lines.begin(),
                                        draft.camera.lines.begin() + static_cast<std::ptrdiff_t>(slot) + 1);
  std::vector<CameraShot> trial(shots.begin(), shots.begin() + static_cast<std::ptrdiff_t>(slot) + 1);
  // From behind the breaker's shoulder and high: the whole cloth, the rack at its far end.
  const Vec3 behind = stroke.cue_at - 3.0 * stroke.aim + Vec3(0, 0, 2.0);
  const TableRect n = layout_.noses;
  const Vec3 corners[] = {Vec3(n.x0, n.y0, 0), Vec3(n.x1, n.y0, 0), Vec3(n.x0, n.y1, 0), Vec3(n.x1, n.y1, 0)};
  for (const CameraShot& option : wide_places(layout_, behind, lines[slot])) {
    // Drawn back along its line until the cloth has room round it (a wide shot's framing is tight).
    const Vec3 back = (option.location - option.target).normalized();
    double distance = (option.location - option.target).norm();
    trial[slot] = option;
    for (; distance <= kOpeningFarthest; distance += 0.1) {
      trial[slot].location = to_millimetre(option.target + distance * back);
      const CameraView view(CameraPose{trial[slot].location, trial[slot].target, false});
      if (std::all_of(std::begin(corners), std::end(corners),
                      [&](const Vec3& p) { return view.contains(p, kOpeningMargin); }))
        break;
    }
    trial[slot].key = shots[slot].key;
    if (!judge(stroke).evaluate(trial, lines, until).ok) continue;
    shots[slot] = trial[slot];
    hold_after(shots, slot);
    draft.camera.comments[slot] = "opening: the whole table, the rack and the breaker's cue ball";
    return true;
  }
  // Nothing fits: the breaker's view takes the whole approach.
  draft.erase(slot);
  draft.camera.shots[slot].key = key_in(stroke, CameraKeyKind::start);
  draft.times[slot] = stroke.begin;
  return false;
}

DirectedCamera Director::run() {
  Draft draft;
  for (int shot = 0; shot < std::max(1, timeline_.shot_count()); ++shot) film(stroke_of(shot), draft);
  return draft.camera;
}

}  // namespace

double LineOfAction::side(const Vec3& p) const {
  return direction.x() * (p.y() - point.y()) - direction.y() * (p.x() - point.x());
}

DirectedCamera direct_camera(const Scene& scene, const Timeline& timeline, const FilmingNotes& notes) {
  if (scene.balls.empty() || timeline.events().empty()) {
    DirectedCamera out;
    CameraShot shot = CameraScript::default_shot(scene);
    shot.key.kind = CameraKeyKind::start;
    shot.location = to_millimetre(shot.location);
    shot.target = to_millimetre(shot.target);
    out.shots.push_back(shot);
    out.comments.push_back("wide: the whole table");
    out.lines.push_back({});
    out.subjects.push_back(-1);
    return out;
  }
  return Director(scene, timeline, notes).run();
}

std::string camera_script_text(const DirectedCamera& camera, const std::string& scene_name) {
  std::string out = "camera\n";
  out += "# Written by the automatic director for " + scene_name +
         ". Each line starts at a moment named by what\n"
         "# happens, so it stays on its moment when the shot changes; edit the numbers to taste.\n";
  for (std::size_t k = 0; k < camera.shots.size(); ++k)
    out += camera_description_text(camera.shots[k]) + "   # " +
           (k < camera.comments.size() ? camera.comments[k] : std::string()) + "\n";
  out += "endcamera\n";
  return out;
}

}  // namespace bsim
