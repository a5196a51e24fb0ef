#include "aim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "simulate.h"
#include "strike.h"
#include "table.h"

namespace bsim {

namespace {

/// Angle `a` brought into (-pi, pi].
double wrap(double a) { return std::remainder(a, 2 * std::numbers::pi); }

double angle_of(const Vec3& v) { return std::atan2(v.y(), v.x()); }

Vec3 unit_at(double a) { return Vec3(std::cos(a), std::sin(a), 0); }

/// Degrees in [0, 360).
double heading_range(double deg) {
  const double h = std::fmod(deg, 360.0);
  return h < 0 ? h + 360.0 : h;
}

std::string metres(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f m", m);
  return text;
}

/// m along the ray p + s u (u a unit vector) at which a ball of radius R centred on it first touches
/// the segment a-b (a cushion's nose line, its ends the jaws), or infinity.
double first_touch(const Vec3& p, const Vec3& u, const Vec3& a, const Vec3& b, double R) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& end : {a, b}) {  // the ends: a circle of radius R about each
    const Vec3 d = p - end;
    const double half_b = d.dot(u), c = d.squaredNorm() - R * R, disc = half_b * half_b - c;
    if (disc >= 0 && -half_b - std::sqrt(disc) >= 0) best = std::min(best, -half_b - std::sqrt(disc));
  }
  const Vec3 along = b - a;
  const double length = along.norm();
  if (length == 0) return best;
  const Vec3 t = along / length, n(-t.y(), t.x(), 0);
  const double side = n.dot(p - a) >= 0 ? 1.0 : -1.0, closing = side * n.dot(u);
  if (closing < 0) {  // the line R off the segment on the ball's side
    const double s = (R - side * n.dot(p - a)) / closing;
    const double at = t.dot(p + s * u - a);
    if (s >= 0 && at >= 0 && at <= length) best = std::min(best, s);
  }
  return best;
}

/// The directions the target ball may leave in and drop: offsets from the direction to the drop
/// circle's centre, rad. Its centre must cross the drop circle before the ball touches a cushion or a
/// jaw (a nose end): a corner pocket seen along its axis is open on both sides, a side pocket seen at a
/// shallow angle is narrowed by its near jaw. Sampled finely; the widest run of open directions is it.
struct Window {
  double lo = 0, hi = 0;  ///< rad, offsets from `toward`
  double toward =
      0;  ///< rad, the direction from the target ball to the drop circle's centre (a cut pocket: its mouth's middle)
  double distance = 0;  ///< m to that point
  bool open() const { return hi > lo; }
  double middle() const { return toward + (lo + hi) / 2; }
};

/// A cut pocket's window: the directions whose line crosses the mouth between the jaw points, passing
/// each jaw's rounding by a ball's radius and reaching the mouth before it touches a cushion. Seen from
/// straight in the window spans the mouth less a ball on each side; seen at a slant the near jaw closes it.
Window cut_window(const Vec3& from, const PocketMouth& mouth, const std::vector<Rail>& rails, double R,
                  bool clear_jaws = true) {
  constexpr int kSamples = 400;
  Window w;
  const Vec3 middle = (mouth.nose[0] + mouth.nose[1]) / 2, to_middle = middle - from;
  w.distance = to_middle.norm();
  w.toward = angle_of(to_middle);
  const double half = std::asin(std::min(1.0, 0.5 * mouth.mouth() / std::max(w.distance, 1e-9)));
  const Vec3 chord = mouth.nose[1] - mouth.nose[0], n(-chord.y(), chord.x(), 0);
  int run = 0, best_run = 0, best_end = -1;
  for (int k = 0; k <= kSamples; ++k) {
    const double offset = -half + 2 * half * k / kSamples;
    const Vec3 u = unit_at(w.toward + offset);
    // Where the line crosses the mouth line, as a share from jaw 0 to jaw 1.
    const double facing = n.dot(u);
    bool open = std::abs(facing) > 1e-12;
    double crosses = 0;
    if (open) {
      crosses = n.dot(mouth.nose[0] - from) / facing;
      const double share = chord.dot(from + crosses * u - mouth.nose[0]) / chord.squaredNorm();
      open = crosses > 0 && share > 0 && share < 1;
    }
    for (int i = 0; open && clear_jaws && i < 2; ++i) {
      const Vec3 c = flat(mouth.round_centre[i]) - from;
      const double along = c.dot(u), miss = (c - along * u).norm();
      open = along < 0 || miss > R + mouth.round_radius;
    }
    for (const Rail& rail : rails) open = open && first_touch(from, u, flat(rail.a), flat(rail.b), R) > crosses;
    run = open ? run + 1 : 0;
    if (run > best_run) {
      best_run = run;
      best_end = k;
    }
  }
  // Seen at a steep slant no line clears both jaws, yet a ball may still go in off the far facing
  // (TP 3.5): then every line through the mouth is tried, and the shots played decide.
  if (best_run < 2) return clear_jaws ? cut_window(from, mouth, rails, R, false) : Window{0, 0, w.toward, w.distance};
  w.hi = -half + 2 * half * best_end / kSamples;
  w.lo = -half + 2 * half * (best_end - best_run + 1) / kSamples;
  return w;
}

Window pocket_window(const Vec3& ball, const PocketMouth& mouth, const std::vector<Rail>& rails, double R) {
  constexpr int kSamples = 400;
  if (mouth.cut) return cut_window(flat(ball), mouth, rails, R);
  Window w;
  const Vec3 from = flat(ball), to_centre = mouth.centre - from;
  w.distance = to_centre.norm();
  w.toward = angle_of(to_centre);
  const double r = mouth.drop_radius;
  if (w.distance <= r)
    return {-std::numbers::pi / 2, std::numbers::pi / 2, w.toward, w.distance};  // over the pocket already
  const double half = std::asin(r / w.distance);
  int run = 0, best_run = 0, best_end = -1;
  for (int k = 0; k <= kSamples; ++k) {
    const double offset = -half + 2 * half * k / kSamples;
    const Vec3 u = unit_at(w.toward + offset);
    const double across = w.distance * std::sin(offset), along = w.distance * std::cos(offset);
    const double enters = along - std::sqrt(std::max(0.0, r * r - across * across));
    bool open = std::abs(across) < r;
    for (const Rail& rail : rails) open = open && first_touch(from, u, flat(rail.a), flat(rail.b), R) > enters;
    run = open ? run + 1 : 0;
    if (run > best_run) {
      best_run = run;
      best_end = k;
    }
  }
  if (best_run < 2) return {0, 0, w.toward, w.distance};
  w.hi = -half + 2 * half * best_end / kSamples;
  w.lo = -half + 2 * half * (best_end - best_run + 1) / kSamples;
  return w;
}

/// One shot played at one heading, and what the target ball did in it.
struct Probe {
  double heading = 0;  ///< degrees
  bool hit = false;    ///< the target ball was struck by a ball
  double error = 0;    ///< rad, its departure direction less the wanted one (when hit)
  bool pots = false;   ///< it dropped into the wanted pocket
  int jaws = 0;        ///< its contacts with the wanted pocket's jaws
  Vec3 target_rest{0, 0, 0};
  Vec3 struck_rest{0, 0, 0};
};

class Solver {
 public:
  explicit Solver(const Scene& scene)
      : written_(scene),
        struck_(scene),
        R_(scene.physics.ball_radius),
        target_(scene.cue().pot_ball),
        pocket_(scene.cue().pot_pocket),
        mouth_(pocket_mouth(scene.pockets[static_cast<std::size_t>(pocket_)], scene.rails)) {}

  AimResult run() {
    const Vec3 target_at = flat(written_.ball(target_).position);
    const Vec3 struck_at = flat(written_.ball(written_.cue().target).position);
    window_ = pocket_window(target_at, mouth_, written_.rails, R_);
    want_ = window_.middle();
    result_.entry = target_at + unit_at(want_) * std::max(0.0, window_.distance);
    result_.ghost = target_at - unit_at(want_) * (2 * R_);
    if (!window_.open())
      return fail("the pocket's jaws close it to " + ball_name(written_, target_) + " from where it lies");
    const double cut = std::abs(wrap(want_ - angle_of(result_.ghost - struck_at))) * 180 / std::numbers::pi;
    if (cut > kMaxCutDeg || (result_.ghost - struck_at).norm() < 1e-9)
      return fail("the cut is thinner than " + fmt_deg(kMaxCutDeg) + " (it would need " + fmt_deg(cut) + ")");
    const double ghost_heading = angle_of(result_.ghost - struck_at) * 180 / std::numbers::pi;
    const Probe best = secant(ghost_heading);
    std::optional<Probe> seed = best.pots ? best : scan(best);
    if (seed) {
      result_.heading_deg = heading_range(middle_of_interval(*seed, best));
      result_.simulations = simulations_;
      return result_;
    }
    // Nothing pots: a ball in the way (a swerve may still get round one, so this is asked only now), or
    // what the ball did at the best heading.
    if (const std::string why = blocked(target_at, result_.entry, {target_}); !why.empty())
      return fail("the path of " + ball_name(written_, target_) + " to the pocket is blocked by " + why);
    if (const std::string why = blocked(struck_at, result_.ghost, {written_.cue().target, target_}); !why.empty())
      return fail("the path of " + struck_name() + " to " + ball_name(written_, target_) + " is blocked by " + why);
    return fail(why_not(best));
  }

 private:
  const Scene& written_;
  Scene struck_;
  double R_;
  int target_, pocket_;
  PocketMouth mouth_;
  Window window_;
  double want_ = 0;   ///< rad, the direction the target ball should leave in
  double slope_ = 0;  ///< rad of departure per degree of heading, from the secant
  AimResult result_;
  int simulations_ = 0;
  bool grazed_ = false;  ///< the secant wanted a thinner cut than the struck ball can make

  AimResult fail(std::string why) {
    result_.failure = "no heading pots " + ball_name(written_, target_) + " in " +
                      pocket_name(written_.pockets, pocket_) + ": " + std::move(why);
    result_.simulations = simulations_;
    return result_;
  }

  /// "the cue ball", or "the struck ball (ball index 2)" when the cue strikes another.
  std::string struck_name() const {
    const int i = written_.cue().target;
    return written_.ball(i).number == 0 ? "the cue ball" : "the struck ball (" + ball_name(written_, i) + ")";
  }

  static std::string fmt_deg(double deg) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", deg);
    std::string out = text;
    if (out.ends_with(".0")) out.resize(out.size() - 2);
    return out + " degrees";
  }

  /// The first ball whose centre lies within two radii of the segment a-b (a ball in the way of a
  /// ball rolling from a to b), or "" when none does.
  std::string blocked(const Vec3& a, const Vec3& b, std::initializer_list<int> except) const {
    const Vec3 ab = b - a;
    const double length = ab.norm();
    int nearest = -1;
    double nearest_along = 0;
    for (int i = 0; i < static_cast<int>(written_.balls.size()); ++i) {
      if (std::find(except.begin(), except.end(), i) != except.end()) continue;
      const Vec3 p = flat(written_.ball(i).position) - a;
      const double along = length > 0 ? std::clamp(p.dot(ab) / length, 0.0, length) : 0.0;
      const double off = (p - (length > 0 ? ab / length : Vec3(0, 0, 0)) * along).norm();
      if (off < 2 * R_ - 1e-9 && (nearest < 0 || along < nearest_along)) {
        nearest = i;
        nearest_along = along;
      }
    }
    return nearest < 0 ? "" : ball_name(written_, nearest);
  }

  Probe play(double heading) {
    ++simulations_;
    strike_heading(written_, heading, struck_);
    const SimulationResult shot = simulate_events(struck_);
    Probe p;
    p.heading = heading;
    for (const Event& e : shot.events) {
      if (e.type != EventType::ball_ball) continue;
      const auto at = std::find(e.balls.begin(), e.balls.end(), target_);
      if (at == e.balls.end()) continue;
      const Vec3& v = e.after[static_cast<std::size_t>(at - e.balls.begin())].velocity;
      p.hit = std::hypot(v.x(), v.y()) > 0;
      p.error = wrap(angle_of(v) - want_);
      break;
    }
    for (const PocketDrop& d : shot.drops) p.pots = p.pots || (d.ball == target_ && d.pocket == pocket_);
    for (const Event& e : shot.events)
      if (e.type == EventType::ball_jaw && e.pocket == pocket_ && e.balls == std::vector<int>{target_}) ++p.jaws;
    p.target_rest = shot.segments[static_cast<std::size_t>(target_)].back().start.position;
    p.struck_rest = shot.segments[static_cast<std::size_t>(written_.cue().target)].back().start.position;
    return p;
  }

  /// Secant on the heading until the target ball leaves in the wanted direction. A heading that misses
  /// the target ball halves the step back toward the last one that hit it.
  Probe secant(double ghost_heading) {
    Probe a = play(ghost_heading);
    if (!a.hit) return a;
    Probe b = play(ghost_heading + 0.01);
    for (int k = 0; k < 12 && b.hit && std::abs(b.error) > 1e-9 && a.hit; ++k) {
      const double de = b.error - a.error;
      if (de == 0) break;
      slope_ = de / (b.heading - a.heading);
      double next = b.heading - b.error / slope_;
      next = std::clamp(next, b.heading - 2.0, b.heading + 2.0);
      Probe c = play(next);
      for (int halve = 0; !c.hit && halve < 8; ++halve) c = play((c.heading + b.heading) / 2);
      grazed_ = grazed_ || !c.hit;
      if (!c.hit) break;
      a = b;
      b = c;
    }
    if (slope_ == 0 && b.hit && a.hit && b.heading != a.heading) slope_ = (b.error - a.error) / (b.heading - a.heading);
    return std::abs(b.error) <= std::abs(a.error) || !a.hit ? b : a;
  }

  /// Degrees of heading that turn the target ball across its window's half width.
  double half_span() const {
    const double half = (window_.hi - window_.lo) / 2;
    return slope_ != 0 ? std::clamp(half / std::abs(slope_), 1e-3, 5.0) : 0.5;
  }

  /// The heading aimed straight did not pot: headings either side, out to the window's width.
  std::optional<Probe> scan(const Probe& best) {
    if (!best.hit) return std::nullopt;
    const double step = half_span() / 2;
    for (int k = 1; k <= 4; ++k)
      for (int side : {-1, 1}) {
        const Probe p = play(best.heading + side * k * step);
        if (p.pots) return p;
      }
    return std::nullopt;
  }

  /// The heading where potting stops on one side of a potting heading, by bisection.
  double edge(const Probe& inside, int side) {
    double in = inside.heading;
    double out = in + side * 1.5 * half_span();
    for (int k = 0; k < 4 && play(out).pots; ++k) {
      in = out;
      out = inside.heading + 2 * (out - inside.heading);
    }
    for (int k = 0; k < 10; ++k) {
      const double mid = (in + out) / 2;
      (play(mid).pots ? in : out) = mid;
    }
    return in;
  }

  /// The middle of the interval of potting headings around `seed`, or the secant's heading should the
  /// middle not pot (an interval with a hole, from a ball in the way).
  double middle_of_interval(const Probe& seed, const Probe& best) {
    const double lo = edge(seed, -1), hi = edge(seed, +1);
    const double middle = (lo + hi) / 2;
    if (play(middle).pots) return middle;
    return best.pots ? best.heading : seed.heading;
  }

  /// Why the best heading found does not pot, from what the target ball did in it.
  std::string why_not(const Probe& best) const {
    const Vec3 centre = mouth_.centre;
    if (!best.hit) {
      const double short_by = (flat(best.struck_rest) - result_.ghost).norm();
      return struck_name() + " cannot reach it (it stops " + metres(short_by) + " short)";
    }
    if (grazed_ && std::abs(best.error) > 1e-3)
      return "the cut is too thin: even grazing it, " + struck_name() + " sends it " +
             fmt_deg(std::abs(best.error) * 180 / std::numbers::pi) + " off the line to the pocket";
    const Vec3 rest = flat(best.target_rest);
    const Vec3 from = flat(written_.ball(target_).position);
    const double travelled = (rest - from).dot(unit_at(want_));
    // How far it must roll to drop: to the drop circle, or a cut pocket's mouth and shelf.
    const double needed = mouth_.cut ? window_.distance + mouth_.shelf() : window_.distance - mouth_.drop_radius;
    if (best.jaws > 0)
      return best.jaws > 1 ? "it rattles in the jaws of " + pocket_name(written_.pockets, pocket_) + " and stays out"
                           : "it hits a jaw of " + pocket_name(written_.pockets, pocket_) + " and stays out";
    if (std::abs(best.error) < 1e-3 && travelled < needed)
      return "it runs out of speed " + metres(needed - travelled) + " short";
    return "sent at the pocket, it stops " + metres((rest - centre).norm()) + " from the pocket's centre";
  }
};

}  // namespace

std::string ball_name(const Scene& scene, int i) {
  const int number = scene.ball(i).number;
  return "ball index " + std::to_string(i) +
         (number == 0 ? " (the cue ball)" : " (the " + std::to_string(number) + ")");
}

std::vector<int> pockets_that_take(const Scene& scene) {
  std::vector<int> found;
  Scene other = scene;
  for (int k = 0; k < static_cast<int>(scene.pockets.size()); ++k) {
    if (k == scene.cue().pot_pocket) continue;
    other.cue().pot_pocket = k;
    if (Solver(other).run().heading_deg) found.push_back(k);
  }
  return found;
}

AimResult aim_cue(const Scene& scene) {
  AimResult result = Solver(scene).run();
  if (result.heading_deg) return result;
  // What the user can do instead: the pockets this stroke does pot the ball in, from where it lies.
  std::string others;
  for (int k : pockets_that_take(scene)) others += (others.empty() ? "" : ", ") + pocket_name(scene.pockets, k);
  result.failure += others.empty() ? "\n  no other pocket takes it from here either"
                                   : "\n  other pockets take it from here: " + others;
  return result;
}

std::string apply_aim(Scene& scene) {
  if (!scene.cue().aims()) return "";
  const AimResult aim = aim_cue(scene);
  if (!aim.heading_deg) return aim.failure;
  const Scene written = scene;
  strike_heading(written, *aim.heading_deg, scene);
  return "";
}

}  // namespace bsim
