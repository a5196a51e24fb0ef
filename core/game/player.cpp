// The player: each shot chosen by trying strokes in the physics itself.
//
// The model, and where it comes from:
//  - Candidate pots and their scoring follow the Computational Pool Olympiad's winners: PickPocket
//    (Smith, "PickPocket: A computer billiards shark", Artificial Intelligence 171, 2007: candidate
//    shots from geometry, each scored by its chance of success and by the best shot it leaves, a
//    safety when no shot is likely enough) and CueCard (Archibald, Altman & Shoham, "Analysis of a
//    winning computational billiards player", IJCAI 2009: a few speeds per geometric shot, each
//    estimated by noisy simulations, a safety below a success threshold, ball in hand by trying places).
//  - The player's noise is FastFiz's `GaussianNoise` (Leckie & Greenspan; FastFiz 0.2 `Noise.cpp`): a
//    zero-mean Gaussian error on each stroke parameter, its deviation the Olympiad's times `noise`.
//  - The cheap geometric chance of a pot (to prune candidates and to score where the cue ball stops)
//    is the margin-of-error argument of Dr. Dave Alciatore's TP 3.4 ("Margin of error based on distance
//    and cut angle"): an aim error dphi turns the object ball's line by about dphi (1 + d_c / (2R cos
//    cut)), and the ball drops while that turn, times the distance to the pocket, stays within the
//    pocket's effective half width; with a Gaussian aim error the chance is an erf.
//
// A shot, step by step:
//  1. candidates: each legal ball and pocket whose cut is under 75 degrees and whose lines (cue ball to
//     ghost ball, ball to the pocket's mouth) no ball blocks, best geometric chance first;
//  2. each aimed by the `pot` solver (aim.h) with a centre-ball reference stroke; the direction the
//     object ball leaves in at that heading is the one every other stroke of the candidate aims for (a
//     secant on the heading, one to three simulations);
//  3. strokes: six speeds (0.9 to 4.5 m/s at the tip) times five heights (draw to follow) times three
//     sides (none, and 0.3 R either way), each played once without noise: it must make the call, and
//     where the cue ball stops is scored by the best next shot (the prior);
//  4. the best strokes by that prior are each played kTrials times with the player's own noise, the
//     same noise draws for every stroke (common random numbers), stopping early once a stroke cannot
//     beat the best so far; a play that makes the call is worth 1 + w (the quality of where that play
//     leaves the cue ball), a miss -kMissCost, and the stroke's score is the mean (CueCard's sampled
//     end states, each valued by its next shot);
//  5. the second ply: the best few strokes by that score are scored again from where their first few
//     noisy plays that made the call left the balls, each leave valued by a small search of the next
//     shot itself (the next legal ball's best pots, aimed by the solver, a few strokes each played
//     without noise, each valued by its geometric chance and the leave after it): P(make) (1 + w mean
//     next value) less the misses' cost (PickPocket's and CueCard's look-ahead);
//  6. a safety when the best chance is low: strokes at each legal ball at several fullnesses and speeds,
//     legal ones (a legal ball first, a cushion after or a ball made) scored by how little the
//     opponent is left; a 9-ball push-out when allowed instead.
// The break: places across the kitchen and two heights, each broken kBreakTrials times with the player's
// noise, the apex ball hit first; the one that makes a ball (without a scratch) most often and leaves
// the best shot after it.
#include "player.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "aim.h"
#include "simulate.h"
#include "strike.h"

namespace bsim {

namespace {

constexpr double kToRad = std::numbers::pi / 180;

constexpr double kMaxCutDegrees = 75;     ///< cuts thinner are not tried
constexpr int kMaxCandidates = 10;        ///< (ball, pocket) candidates aimed, best geometric chance first
constexpr int kTrials = 64;               ///< noisy plays per stroke
constexpr int kTrialStrokes = 32;         ///< strokes given noisy plays, best prior first
constexpr int kFinalists = 10;            ///< strokes whose leaves get a second ply, best score first
constexpr int kLeavesSearched = 8;        ///< noisy leaves per finalist searched for the next shot
constexpr int kBreakTrials = 8;           ///< noisy plays of each break place
constexpr int kNextCandidates = 4;        ///< next (ball, pocket) pots tried from a leave
constexpr double kPositionWeight = 2.0;   ///< a pot made is worth 1 + w (the leave's quality)
constexpr double kMissCost = 1.0;         ///< a pot missed costs this (the opponent's turn)
constexpr double kSafetyBelow = 0.45;     ///< a pot less likely than this gives way to a safety
constexpr double kLeaveSigma = 2.5;       ///< the leave is judged at this many times the player's aim deviation
constexpr double kTakePushOut = 0.5;      ///< the pot chance from which a player takes a push-out
constexpr double kBreakBallSpeed = 10.7;  ///< m/s, the cue ball's off the break (Onoda: men pros' mean)

/// The painted numbers of balls an opponent (or the player, next shot) may hit first.
using Numbers = std::vector<int>;

bool has(const Numbers& list, int n) { return std::find(list.begin(), list.end(), n) != list.end(); }

Vec3 on_bed(const Vec3& v) { return Vec3(v.x(), v.y(), 0); }

double heading_of(const Vec3& v) { return std::atan2(v.y(), v.x()) / kToRad; }

/// What a simulated shot did, as the player reads it.
struct Outcome {
  bool scratch = false;          ///< the cue ball went down
  int first_hit = -1;            ///< painted number of the first ball the cue ball touched
  bool cushion_after = false;    ///< a ball met a cushion or a jaw after that contact
  std::vector<int> made;         ///< painted numbers of object balls made
  std::vector<int> made_pocket;  ///< and their pockets
  std::vector<Ball> rest;        ///< the balls where they stop (pocket >= 0: down)
  bool watch_hit = false;        ///< the watched ball was struck
  double watch_dir = 0;          ///< rad, the direction it left in
  bool makes(int number, int pocket) const {
    for (std::size_t i = 0; i < made.size(); ++i)
      if (made[i] == number && made_pocket[i] == pocket) return true;
    return false;
  }
};

/// A shot chosen, with what the choice is worth.
struct Choice {
  double heading = 0;
  Stroke stroke;
  std::optional<Vec3> place;
  ShotCall call;
  double chance = 0;
  double score = -1e300;
};

/// A (ball, pocket) pot from one cue ball place.
struct Candidate {
  int ball = -1;    ///< file-order index
  int pocket = -1;  ///< Scene::pockets index
  double ease = 0;  ///< geometric chance
  std::vector<Ball> lie;
  std::optional<Vec3> place;
};

/// One stroke of a candidate, aimed and played once without noise.
struct Try {
  std::size_t candidate = 0;
  Stroke stroke;
  double heading = 0;
  double quality = 0;  ///< of the leave
  double prior = 0;
  double chance = 0;                      ///< share of noisy plays that make the call
  double score = 0;                       ///< their mean value
  std::vector<std::vector<Ball>> leaves;  ///< the first few noisy plays made: where the balls stopped
};

/// A standard normal deviate: Marsaglia's polar method (the first of its pair).
double gaussian(SplitMix64& random) {
  for (;;) {
    const double u = 2 * random.uniform() - 1, v = 2 * random.uniform() - 1;
    const double s = u * u + v * v;
    if (s > 0 && s < 1) return u * std::sqrt(-2 * std::log(s) / s);
  }
}

/// A seed of its own for trial `k` of a plan seeded `seed`.
std::uint64_t trial_seed(std::uint64_t seed, std::uint64_t k) {
  SplitMix64 mix(seed ^ (0xD1B54A32D192ED03ull * (k + 1)));
  return mix.next();
}

class Planner {
 public:
  Planner(const Scene& table, const ShotRules& rules, const PlayerSkill& skill, std::uint64_t seed);

  PlannedShot plan();
  /// The best pot's chance from the table as it lies (ball in hand as the rules say).
  double best_pot_chance();

 private:
  Scene work_;               ///< the one-shot scene every trial plays (its balls set per trial)
  std::vector<Ball> table_;  ///< the balls as they lie, at rest
  const ShotRules& rules_;
  double noise_;
  bool look_ahead_;
  std::uint64_t seed_;
  double R_;
  int cue_ = -1;
  int sims_ = 0;
  bool eight_ball_;
  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;  ///< the bed inside the cushion noses
  std::vector<Vec3> mouths_;                  ///< each pocket's aim point: the middle of its mouth

  // The geometry (no simulation).
  bool clear(const std::vector<Ball>& lie, const Vec3& a, const Vec3& b, int skip1, int skip2) const;
  double ease(const std::vector<Ball>& lie, int ball, int pocket, double sigma, double* cut = nullptr) const;
  double best_ease(const std::vector<Ball>& lie, const Numbers& targets, double sigma) const;
  double sigma_play() const { return kNoiseHeadingDeg * kToRad * std::max(noise_, 0.5) * 2; }
  double sigma_leave() const { return kNoiseHeadingDeg * kToRad * std::max(noise_, 1.0) * kLeaveSigma; }
  int index_of(const std::vector<Ball>& lie, int number) const;
  Numbers next_targets(const std::vector<Ball>& lie, int made_number) const;
  Numbers opponent_targets(const std::vector<Ball>& lie) const;
  bool free_place(const std::vector<Ball>& lie, const Vec3& p, bool kitchen) const;

  // The physics.
  Outcome play(const std::vector<Ball>& lie, double heading, const Stroke& stroke, int watch = -1);
  bool pot_made(const Outcome& o, int number, int pocket) const { return pot_made(o, number, pocket, rules_.targets); }
  bool pot_made(const Outcome& o, int number, int pocket, const Numbers& targets) const;

  // Pots.
  std::vector<Candidate> candidates(const std::vector<Ball>& lie, const std::optional<Vec3>& place) const {
    return candidates(lie, place, rules_.targets);
  }
  std::vector<Candidate> candidates(const std::vector<Ball>& lie, const std::optional<Vec3>& place,
                                    const Numbers& targets) const;
  void try_strokes(const std::vector<Candidate>& list, std::size_t c, std::vector<Try>& tries);
  std::optional<double> reference_heading(const Candidate& cand, const Stroke& reference);
  std::optional<double> aim_stroke(const Candidate& cand, double want, double start, const Stroke& stroke,
                                   Outcome& out);
  std::optional<Choice> best_pot(const std::vector<Candidate>& list);
  double leave_quality(const Outcome& o, int made_number) const;
  void chance_of(const Candidate& cand, Try& t, double bound);
  double next_value(const std::vector<Ball>& lie, int made_number);
  double next_pot_value(const Candidate& cand, const Numbers& targets);
  void second_ply(const std::vector<Candidate>& list, std::vector<Try>& finalists);
  std::optional<Choice> in_hand_pot();

  // The rest.
  PlannedShot break_shot();
  double break_value(const PlannedShot& s, int apex_number);
  std::optional<Choice> safety(const std::vector<Ball>& lie);
  double safety_value(const Outcome& o);
  std::optional<Choice> push_out(const std::vector<Ball>& lie);
  Vec3 hand_place() const;
  PlannedShot planned(const Choice& c) const;
};

Planner::Planner(const Scene& table, const ShotRules& rules, const PlayerSkill& skill, std::uint64_t seed)
    : rules_(rules),
      noise_(skill.noise),
      look_ahead_(skill.look_ahead),
      seed_(seed),
      R_(table.physics.ball_radius),
      eight_ball_(rules.winning_ball == 8) {
  work_.name = table.name;
  work_.rails = table.rails;
  work_.pockets = table.pockets;
  work_.physics = table.physics;
  work_.cues = {Cue{}};
  table_ = table.balls;
  for (std::size_t i = 0; i < table_.size(); ++i) {
    Ball& b = table_[i];
    b.velocity.setZero();
    b.spin.setZero();
    if (b.number == 0 && cue_ < 0) cue_ = static_cast<int>(i);
  }
  work_.cue().target = std::max(cue_, 0);
  bool first = true;
  for (const Rail& r : table.rails)
    for (const Vec3& p : {r.a, r.b}) {
      x0_ = first ? p.x() : std::min(x0_, p.x());
      x1_ = first ? p.x() : std::max(x1_, p.x());
      y0_ = first ? p.y() : std::min(y0_, p.y());
      y1_ = first ? p.y() : std::max(y1_, p.y());
      first = false;
    }
  if (first) {
    x0_ = -kStandardTable.half_length, x1_ = kStandardTable.half_length;
    y0_ = -kStandardTable.half_width, y1_ = kStandardTable.half_width;
  }
  for (const Pocket& p : table.pockets) mouths_.push_back(p.cut ? on_bed((p.jaw[0] + p.jaw[1]) / 2) : on_bed(p.center));
}

// ---- geometry ------------------------------------------------------------------------------------

bool Planner::clear(const std::vector<Ball>& lie, const Vec3& a, const Vec3& b, int skip1, int skip2) const {
  const Vec3 ab = on_bed(b - a);
  const double length2 = ab.squaredNorm();
  for (int i = 0; i < static_cast<int>(lie.size()); ++i) {
    if (i == skip1 || i == skip2 || lie[static_cast<std::size_t>(i)].pocket >= 0) continue;
    const Vec3 ap = on_bed(lie[static_cast<std::size_t>(i)].position - a);
    const double t = length2 > 0 ? std::clamp(ap.dot(ab) / length2, 0.0, 1.0) : 0.0;
    if ((ap - t * ab).norm() < 2 * R_ - 1e-9) return false;
  }
  return true;
}

/// The geometric chance of potting `ball` in `pocket` from where the cue ball lies, with an aim error
/// of deviation `sigma` rad (TP 3.4); 0 when the cut is too thin, the approach closes the pocket or a
/// ball blocks a line.
double Planner::ease(const std::vector<Ball>& lie, int ball, int pocket, double sigma, double* cut_out) const {
  if (cue_ < 0 || ball < 0) return 0;
  const Vec3 c = on_bed(lie[static_cast<std::size_t>(cue_)].position);
  const Vec3 o = on_bed(lie[static_cast<std::size_t>(ball)].position);
  const Pocket& pk = work_.pockets[static_cast<std::size_t>(pocket)];
  const Vec3 m = mouths_[static_cast<std::size_t>(pocket)];
  const double d_o = (m - o).norm();
  if (d_o < 1e-6) return 1;
  const Vec3 u = (m - o) / d_o;
  const Vec3 ghost = o - 2 * R_ * u;
  const Vec3 v = ghost - c;
  const double d_c = v.norm();
  if (d_c < 1e-6) return 0;
  const double cos_cut = std::clamp(v.dot(u) / d_c, -1.0, 1.0);
  const double cut = std::acos(cos_cut) / kToRad;
  if (cut_out) *cut_out = cut;
  if (cut > kMaxCutDegrees) return 0;
  // The pocket's effective half width shrinks as the ball comes in across its axis.
  double w = 0.03;
  if (pk.cut) {
    const double across = std::acos(std::clamp(u.dot(on_bed(pk.axis).normalized()), -1.0, 1.0)) / kToRad;
    const double closes = pk.kind == PocketKind::side ? 62.0 : 72.0;
    if (across >= closes) return 0;
    w *= std::sqrt(1 - across / closes) * (pk.kind == PocketKind::side ? 1.0 : 1.1);
  }
  if (!clear(lie, c, ghost, cue_, ball) || !clear(lie, o, m, ball, cue_)) return 0;
  const double turn = 1 + d_c / (2 * R_ * std::max(cos_cut, 0.2));
  const double margin = w / d_o / turn;
  return std::erf(margin / (std::sqrt(2.0) * sigma));
}

double Planner::best_ease(const std::vector<Ball>& lie, const Numbers& targets, double sigma) const {
  double best = 0;
  for (int n : targets) {
    const int i = index_of(lie, n);
    if (i < 0) continue;
    for (int p = 0; p < static_cast<int>(work_.pockets.size()); ++p) best = std::max(best, ease(lie, i, p, sigma));
  }
  return best;
}

int Planner::index_of(const std::vector<Ball>& lie, int number) const {
  for (std::size_t i = 0; i < lie.size(); ++i)
    if (lie[i].number == number && lie[i].pocket < 0) return static_cast<int>(i);
  return -1;
}

/// The balls the player may hit first next shot after making `made_number` (legally) from `lie`: 9-ball,
/// the lowest on the table; 8-ball, the rest of the made ball's group, or the 8. Empty: the game is won.
Numbers Planner::next_targets(const std::vector<Ball>& lie, int made_number) const {
  Numbers on;
  for (const Ball& b : lie)
    if (b.number > 0 && b.pocket < 0) on.push_back(b.number);
  std::sort(on.begin(), on.end());
  if (made_number == rules_.winning_ball) return {};
  if (!eight_ball_) return on.empty() ? Numbers{} : Numbers{on.front()};
  const bool solids = made_number < 8;
  Numbers group;
  for (int n : on)
    if (n != 8 && (n < 8) == solids) group.push_back(n);
  if (group.empty() && has(on, 8)) group.push_back(8);
  return group;
}

/// The opponent's legal balls on `lie` (8-ball: the group the shooter does not play).
Numbers Planner::opponent_targets(const std::vector<Ball>& lie) const {
  Numbers on;
  for (const Ball& b : lie)
    if (b.number > 0 && b.pocket < 0) on.push_back(b.number);
  std::sort(on.begin(), on.end());
  if (!eight_ball_) return on.empty() ? Numbers{} : Numbers{on.front()};
  bool mine_solid = false, mine_stripe = false;
  for (int n : rules_.targets) {
    if (n < 8) mine_solid = true;
    if (n > 8) mine_stripe = true;
  }
  Numbers theirs;
  for (int n : on) {
    if (n == 8) continue;
    const bool solid = n < 8;
    if ((mine_solid && mine_stripe) || (!mine_solid && !mine_stripe) || (solid ? !mine_solid : !mine_stripe))
      theirs.push_back(n);
  }
  if (theirs.empty() && has(on, 8)) theirs.push_back(8);
  return theirs;
}

bool Planner::free_place(const std::vector<Ball>& lie, const Vec3& p, bool kitchen) const {
  const double margin = R_ + 0.002;
  if (p.x() < x0_ + margin || p.x() > x1_ - margin || p.y() < y0_ + margin || p.y() > y1_ - margin) return false;
  if (kitchen && p.x() > -0.635) return false;
  for (std::size_t i = 0; i < lie.size(); ++i) {
    if (static_cast<int>(i) == cue_ || lie[i].pocket >= 0) continue;
    if ((on_bed(lie[i].position) - on_bed(p)).norm() < 2 * R_ + 0.002) return false;
  }
  for (std::size_t k = 0; k < work_.pockets.size(); ++k) {
    const Pocket& pk = work_.pockets[k];
    if ((on_bed(pk.center) - on_bed(p)).norm() < pk.radius + 2 * R_) return false;
    if ((mouths_[k] - on_bed(p)).norm() < 3 * R_) return false;
  }
  return true;
}

// ---- the physics ---------------------------------------------------------------------------------

Outcome Planner::play(const std::vector<Ball>& lie, double heading, const Stroke& stroke, int watch) {
  ++sims_;
  work_.balls = lie;
  Cue& cue = work_.cue();
  cue.heading_deg = heading;
  cue.stroke = stroke;
  const SimulationResult r = simulate_events(work_);
  Outcome o;
  double first_time = -1;
  for (const Event& e : r.events) {
    if (e.type == EventType::ball_ball) {
      for (const Contact& c : e.contacts) {
        if (o.first_hit < 0 && (c.a == cue_ || c.b == cue_)) {
          o.first_hit = lie[static_cast<std::size_t>(c.a == cue_ ? c.b : c.a)].number;
          first_time = c.time;
        }
      }
      if (watch >= 0 && !o.watch_hit)
        for (std::size_t k = 0; k < e.balls.size(); ++k)
          if (e.balls[k] == watch) {
            const Vec3& v = e.after[k].velocity;
            o.watch_hit = std::hypot(v.x(), v.y()) > 0;
            o.watch_dir = std::atan2(v.y(), v.x());
          }
    } else if ((e.type == EventType::ball_rail || e.type == EventType::ball_jaw) && first_time >= 0 &&
               e.time >= first_time) {
      o.cushion_after = true;
    }
  }
  for (const PocketDrop& d : r.drops) {
    const int number = lie[static_cast<std::size_t>(d.ball)].number;
    if (number == 0) {
      o.scratch = true;
    } else {
      o.made.push_back(number);
      o.made_pocket.push_back(d.pocket);
    }
  }
  o.rest = lie;
  for (std::size_t i = 0; i < lie.size(); ++i) {
    const MotionSegment& last = r.segments[i].back();
    o.rest[i].position = last.start.position;
    if (last.start.motion == Motion::pocketed || last.start.motion == Motion::falling) o.rest[i].pocket = last.pocket;
  }
  return o;
}

/// The called ball in the called pocket on a legal shot: a legal ball first, no scratch, the winning
/// ball not lost on the way (8-ball: the 8 made with any other call).
bool Planner::pot_made(const Outcome& o, int number, int pocket, const Numbers& targets) const {
  if (o.scratch || !has(targets, o.first_hit) || !o.makes(number, pocket)) return false;
  if (eight_ball_ && number != 8 && has(o.made, 8)) return false;
  return true;
}

// ---- pots ----------------------------------------------------------------------------------------

std::vector<Candidate> Planner::candidates(const std::vector<Ball>& lie, const std::optional<Vec3>& place,
                                           const Numbers& targets) const {
  std::vector<Candidate> list;
  for (int n : targets) {
    if (eight_ball_ && n == 8 && !(targets.size() == 1)) continue;
    const int i = index_of(lie, n);
    if (i < 0) continue;
    for (int p = 0; p < static_cast<int>(work_.pockets.size()); ++p) {
      const double e = ease(lie, i, p, sigma_play());
      if (e <= 0.02) continue;
      list.push_back({i, p, e, lie, place});
    }
  }
  std::stable_sort(list.begin(), list.end(), [](const Candidate& a, const Candidate& b) { return a.ease > b.ease; });
  if (list.size() > static_cast<std::size_t>(kMaxCandidates)) list.resize(kMaxCandidates);
  return list;
}

/// The heading that sends the candidate's ball off in direction `want` (rad) with `stroke`, by a secant
/// from `start` (deg); `out` is the noise-free shot at the heading returned.
std::optional<double> Planner::aim_stroke(const Candidate& cand, double want, double start, const Stroke& stroke,
                                          Outcome& out) {
  double a = start;
  out = play(cand.lie, a, stroke, cand.ball);
  if (!out.watch_hit) return std::nullopt;
  double ea = std::remainder(out.watch_dir - want, 2 * std::numbers::pi);
  if (std::abs(ea) < 2e-3) return a;
  double b = a + 0.05;
  Outcome ob = play(cand.lie, b, stroke, cand.ball);
  for (int k = 0; k < 4 && ob.watch_hit; ++k) {
    const double eb = std::remainder(ob.watch_dir - want, 2 * std::numbers::pi);
    if (std::abs(eb) < 2e-3) {
      out = ob;
      return b;
    }
    if (eb == ea) break;
    const double next = std::clamp(b - eb * (b - a) / (eb - ea), b - 3.0, b + 3.0);
    a = b;
    ea = eb;
    b = next;
    ob = play(cand.lie, b, stroke, cand.ball);
  }
  if (!ob.watch_hit) return std::nullopt;
  out = ob;
  return b;
}

/// The stroke a candidate is first aimed with: 2 m/s through the centre.
Stroke reference_stroke() {
  Stroke reference;
  reference.speed = 2.0;
  return reference;
}

/// The `pot` solver's heading for candidate `cand` with `reference` (its simulations counted), or none.
std::optional<double> Planner::reference_heading(const Candidate& cand, const Stroke& reference) {
  Scene one = work_;
  one.balls = cand.lie;
  one.cue().pot_ball = cand.ball;
  one.cue().pot_pocket = cand.pocket;
  one.cue().stroke = reference;
  const AimResult aim = aim_cue(one);
  sims_ += aim.simulations;
  return aim.heading_deg;
}

/// Aims candidate `c` with the solver, then plays its strokes once each without noise.
void Planner::try_strokes(const std::vector<Candidate>& list, std::size_t c, std::vector<Try>& tries) {
  const Candidate& cand = list[c];
  const int number = cand.lie[static_cast<std::size_t>(cand.ball)].number;
  const Stroke reference = reference_stroke();
  const std::optional<double> heading = reference_heading(cand, reference);
  if (!heading) return;
  const Outcome ref = play(cand.lie, *heading, reference, cand.ball);
  if (!ref.watch_hit) return;
  for (double speed : {0.9, 1.3, 1.8, 2.5, 3.4, 4.5})
    for (double height : {-0.45, -0.2, 0.0, 0.2, 0.45})
      for (double side : {0.0, -0.3, 0.3}) {
        Stroke s;
        s.speed = speed;
        s.height = height;
        s.side = side;
        Outcome o;
        const std::optional<double> h = aim_stroke(cand, ref.watch_dir, *heading, s, o);
        if (!h || !pot_made(o, number, cand.pocket)) continue;
        Try t{c, s, *h, 0, 0, 0, 0, {}};
        t.quality = leave_quality(o, number);
        t.prior = cand.ease * (1 + kPositionWeight * t.quality) - (1 - cand.ease) * kMissCost;
        tries.push_back(t);
      }
}

/// How good the next shot is from where `o` leaves the balls after making `made_number`: the best next
/// legal ball's geometric chance at a deviation wider than the player's own (a comfortable shot scores
/// near 1, a hidden or long thin one near 0); 1 when the game is won.
double Planner::leave_quality(const Outcome& o, int made_number) const {
  const Numbers next = next_targets(o.rest, made_number);
  return next.empty() ? 1.0 : best_ease(o.rest, next, sigma_leave());
}

/// kTrials noisy plays of `t`: the share that make the call (t.chance) and the mean value (t.score: a pot
/// made is worth 1 + w times the quality of where that play leaves the balls, a miss -kMissCost); the
/// first few leaves of plays made are kept for the second ply. Stops early once even every remaining
/// play made with a perfect leave could not reach `bound` (the score is then below the truth).
void Planner::chance_of(const Candidate& cand, Try& t, double bound) {
  const int number = cand.lie[static_cast<std::size_t>(cand.ball)].number;
  int made = 0;
  double value = 0;
  t.chance = 0;
  t.score = -kMissCost;
  const int trials = noise_ > 0 ? kTrials : 1;  // no noise: every play is the same
  for (int k = 0; k < trials; ++k) {
    if ((value + (trials - k) * (1 + kPositionWeight)) / trials < bound) return;
    SplitMix64 random(trial_seed(seed_, static_cast<std::uint64_t>(k)));
    double heading = t.heading;
    Stroke stroke = t.stroke;
    apply_noise(noise_, R_, random, heading, stroke);
    Outcome o = play(cand.lie, heading, stroke);
    if (pot_made(o, number, cand.pocket)) {
      ++made;
      value += 1 + kPositionWeight * leave_quality(o, number);
      if (t.leaves.size() < static_cast<std::size_t>(kLeavesSearched)) t.leaves.push_back(std::move(o.rest));
    } else {
      value -= kMissCost;
    }
  }
  t.chance = static_cast<double>(made) / trials;
  t.score = value / trials;
}

/// The best next pot of `cand` (a next-shot candidate) played without noise from a few strokes: its
/// geometric chance times 1 + w times the quality of the leave after it (0 when no stroke makes it).
double Planner::next_pot_value(const Candidate& cand, const Numbers& targets) {
  const int number = cand.lie[static_cast<std::size_t>(cand.ball)].number;
  const Stroke reference = reference_stroke();
  const std::optional<double> heading = reference_heading(cand, reference);
  if (!heading) return 0;
  const Outcome ref = play(cand.lie, *heading, reference, cand.ball);
  if (!ref.watch_hit) return 0;
  double best = 0;
  for (double speed : {0.9, 1.5, 2.4, 3.6})
    for (double height : {-0.35, 0.0, 0.35}) {
      Stroke s;
      s.speed = speed;
      s.height = height;
      Outcome o;
      const std::optional<double> h = aim_stroke(cand, ref.watch_dir, *heading, s, o);
      if (!h || !pot_made(o, number, cand.pocket, targets)) continue;
      best = std::max(best, cand.ease * (1 + kPositionWeight * leave_quality(o, number)));
    }
  return best;
}

/// The second ply: how good the next shot is from `lie` after making `made_number`, by a small stroke
/// search over the next legal ball's best few pots, as a share of a sure pot with a perfect leave.
double Planner::next_value(const std::vector<Ball>& lie, int made_number) {
  const Numbers next = next_targets(lie, made_number);
  if (next.empty()) return 1.0;
  if (lie[static_cast<std::size_t>(cue_)].pocket >= 0) return 0.0;
  std::vector<Candidate> list = candidates(lie, std::nullopt, next);
  if (list.size() > static_cast<std::size_t>(kNextCandidates)) list.resize(kNextCandidates);
  double best = 0;
  for (const Candidate& cand : list) best = std::max(best, next_pot_value(cand, next));
  return best / (1 + kPositionWeight);
}

/// Re-scores each finalist by the second ply over its kept leaves: P(make) (1 + w mean next value) less
/// the misses' cost.
void Planner::second_ply(const std::vector<Candidate>& list, std::vector<Try>& finalists) {
  for (Try& t : finalists) {
    if (t.leaves.empty()) continue;
    const Candidate& cand = list[t.candidate];
    const int number = cand.lie[static_cast<std::size_t>(cand.ball)].number;
    double sum = 0;
    for (const std::vector<Ball>& leaf : t.leaves) sum += next_value(leaf, number);
    const double mean = sum / static_cast<double>(t.leaves.size());
    t.score = t.chance * (1 + kPositionWeight * mean) - (1 - t.chance) * kMissCost;
  }
}

std::optional<Choice> Planner::best_pot(const std::vector<Candidate>& list) {
  std::vector<Try> tries;
  for (std::size_t c = 0; c < list.size(); ++c) try_strokes(list, c, tries);
  std::stable_sort(tries.begin(), tries.end(), [](const Try& a, const Try& b) { return a.prior > b.prior; });
  if (tries.size() > static_cast<std::size_t>(kTrialStrokes)) tries.resize(kTrialStrokes);
  double bound = -kMissCost;
  for (Try& t : tries) {
    chance_of(list[t.candidate], t, bound - 0.5);
    bound = std::max(bound, t.score);
  }
  std::stable_sort(tries.begin(), tries.end(), [](const Try& a, const Try& b) { return a.score > b.score; });
  if (tries.size() > static_cast<std::size_t>(kFinalists)) tries.resize(kFinalists);
  if (noise_ > 0 && look_ahead_) second_ply(list, tries);
  std::optional<Choice> best;
  for (const Try& t : tries) {
    if (best && t.score <= best->score) continue;
    const Candidate& cand = list[t.candidate];
    Choice c;
    c.heading = t.heading;
    c.stroke = t.stroke;
    c.place = cand.place;
    c.call.ball = cand.lie[static_cast<std::size_t>(cand.ball)].number;
    c.call.pocket = cand.pocket;
    c.chance = t.chance;
    c.score = t.score;
    best = c;
  }
  return best;
}

/// Ball in hand: places behind each open (ball, pocket) line's ghost ball, at straight and at cut
/// angles, the best few by the geometric chance tried in full.
std::optional<Choice> Planner::in_hand_pot() {
  const bool kitchen = rules_.in_hand == InHand::kitchen;
  std::vector<Candidate> places;
  std::vector<Ball> lie = table_;
  for (int n : rules_.targets) {
    if (eight_ball_ && n == 8 && rules_.targets.size() != 1) continue;
    const int i = index_of(lie, n);
    if (i < 0 || (kitchen && lie[static_cast<std::size_t>(i)].position.x() < -0.635 + R_)) continue;
    const Vec3 o = on_bed(lie[static_cast<std::size_t>(i)].position);
    for (int p = 0; p < static_cast<int>(work_.pockets.size()); ++p) {
      const Vec3 u = (mouths_[static_cast<std::size_t>(p)] - o).normalized();
      const Vec3 ghost = o - 2 * R_ * u;
      for (double cut : {0.0, 15.0, -15.0, 30.0, -30.0})
        for (double back : {0.2, 0.35}) {
          const double a = std::atan2(-u.y(), -u.x()) + cut * kToRad;
          Vec3 at = ghost + back * Vec3(std::cos(a), std::sin(a), 0);
          at.z() = R_;
          if (!free_place(lie, at, kitchen)) continue;
          std::vector<Ball> placed = lie;
          placed[static_cast<std::size_t>(cue_)].position = at;
          placed[static_cast<std::size_t>(cue_)].pocket = -1;
          const double e = ease(placed, i, p, sigma_play());
          // Some cut keeps the cue ball free to move on; a dead straight shot is a little less good.
          if (e > 0.02) places.push_back({i, p, e * (cut == 0 ? 0.97 : 1.0), placed, at});
        }
    }
  }
  std::stable_sort(places.begin(), places.end(),
                   [](const Candidate& a, const Candidate& b) { return a.ease > b.ease; });
  // The best few, at most two per (ball, pocket).
  std::vector<Candidate> chosen;
  for (const Candidate& c : places) {
    int same = 0;
    for (const Candidate& d : chosen) same += d.ball == c.ball && d.pocket == c.pocket;
    if (same < 2) chosen.push_back(c);
    if (chosen.size() >= 6) break;
  }
  return best_pot(chosen);
}

double Planner::best_pot_chance() {
  std::optional<Choice> pot;
  if (rules_.in_hand != InHand::none && cue_ >= 0)
    pot = in_hand_pot();
  else if (cue_ >= 0 && table_[static_cast<std::size_t>(cue_)].pocket < 0)
    pot = best_pot(candidates(table_, std::nullopt));
  return pot ? pot->chance : 0.0;
}

// ---- the break, safeties, push-outs --------------------------------------------------------------

PlannedShot Planner::break_shot() {
  // The apex ball: the 1 in 9-ball, else the object ball nearest the head of the table.
  int apex = -1;
  for (int i = 0; i < static_cast<int>(table_.size()); ++i) {
    const Ball& b = table_[static_cast<std::size_t>(i)];
    if (b.number == 0 || b.pocket >= 0) continue;
    if (apex < 0) {
      apex = i;
      continue;
    }
    const Ball& a = table_[static_cast<std::size_t>(apex)];
    if (!eight_ball_ && (a.number == 1 || b.number == 1)) {
      if (b.number == 1) apex = i;
    } else if (b.position.x() < a.position.x()) {
      apex = i;
    }
  }
  const Vec3 aim = apex >= 0 ? table_[static_cast<std::size_t>(apex)].position : Vec3(kFootSpotX, kFootSpotY, R_);
  Stroke unit;
  unit.speed = 1;
  const double gain = strike(unit, 0, work_.physics).velocity.norm();
  PlannedShot shot;
  double best = -1e300;
  // Places across the kitchen and two heights, each broken a few times with the player's noise: the
  // one that makes a ball most often and leaves the best shot after it.
  for (double y : {0.08, -0.08, 0.16, -0.16, 0.0, 0.3, -0.3, 0.45, -0.45})
    for (double height : {-0.1, -0.3}) {
      const Vec3 at(-0.64, y, R_);
      if (!free_place(table_, at, true)) continue;
      PlannedShot s;
      s.place = at;
      s.heading_deg = heading_of(aim - at);
      s.stroke.speed = std::min(Stroke::kMaxSpeed, kBreakBallSpeed / std::max(gain, 1e-6));
      s.stroke.height = height;
      const double value = apex >= 0 ? break_value(s, table_[static_cast<std::size_t>(apex)].number) : 0;
      if (value > best) {
        best = value;
        shot = s;
      }
    }
  return shot;
}

/// The mean value of kBreakTrials noisy plays of break `s`: -1 a foul (the apex not first, a scratch),
/// 0 nothing made, 1 + w times the next shot's geometric chance a ball made (the winning ball made: 1 + w).
double Planner::break_value(const PlannedShot& s, int apex_number) {
  std::vector<Ball> lie = table_;
  lie[static_cast<std::size_t>(cue_)].position = *s.place;
  lie[static_cast<std::size_t>(cue_)].pocket = -1;
  double total = 0;
  const int trials = noise_ > 0 ? kBreakTrials : 1;
  for (int k = 0; k < trials; ++k) {
    SplitMix64 random(trial_seed(seed_ ^ 0xb4eaull, static_cast<std::uint64_t>(k)));
    double heading = s.heading_deg;
    Stroke stroke = s.stroke;
    apply_noise(noise_, R_, random, heading, stroke);
    const Outcome o = play(lie, heading, stroke);
    if (o.scratch || o.first_hit != apex_number || (eight_ball_ && has(o.made, 8))) {
      total -= 1;
    } else if (has(o.made, rules_.winning_ball)) {
      total += 1 + kPositionWeight;
    } else if (!o.made.empty()) {
      Numbers next;
      for (const Ball& b : o.rest)
        if (b.number > 0 && b.pocket < 0 && (!eight_ball_ || b.number != 8)) next.push_back(b.number);
      std::sort(next.begin(), next.end());
      if (!eight_ball_ && !next.empty()) next.erase(next.begin() + 1, next.end());
      total += 1 + kPositionWeight * best_ease(o.rest, next, sigma_leave());
    }
  }
  return total / trials;
}

/// What a legal safety leaves, higher the better: 1 less the opponent's best geometric chance; a ball
/// made legally keeps the table (worth more). -1 for an illegal shot.
double Planner::safety_value(const Outcome& o) {
  if (o.scratch || !has(rules_.targets, o.first_hit)) return -1;
  if (eight_ball_ && has(o.made, 8)) return -1;
  if (!o.made.empty()) return 1.5;
  if (!o.cushion_after) return -1;
  return 1 - best_ease(o.rest, opponent_targets(o.rest), sigma_leave());
}

std::optional<Choice> Planner::safety(const std::vector<Ball>& lie) {
  if (cue_ < 0) return std::nullopt;
  const Vec3 c = on_bed(lie[static_cast<std::size_t>(cue_)].position);
  std::vector<Choice> found;
  auto consider = [&](double heading, double speed) {
    Stroke s;
    s.speed = speed;
    const double v = safety_value(play(lie, heading, s));
    if (v < 0) return;
    Choice ch;
    ch.heading = heading;
    ch.stroke = s;
    ch.call.safety = true;
    ch.score = v;
    found.push_back(ch);
  };
  for (int n : rules_.targets) {
    const int i = index_of(lie, n);
    if (i < 0) continue;
    const Vec3 o = on_bed(lie[static_cast<std::size_t>(i)].position);
    const double d = (o - c).norm();
    if (!clear(lie, c, o, cue_, i)) continue;
    for (double f : {-0.8, -0.5, -0.25, 0.0, 0.25, 0.5, 0.8})
      for (double speed : {0.9, 1.6, 2.6, 4.0})
        consider(heading_of(o - c) + std::asin(std::clamp(f * 2 * R_ / d, -1.0, 1.0)) / kToRad, speed);
  }
  if (found.empty())  // every legal ball hidden: kicks, all round
    for (int k = 0; k < 120; ++k) consider(3.0 * k, 2.6);
  if (found.empty()) return std::nullopt;
  std::stable_sort(found.begin(), found.end(), [](const Choice& a, const Choice& b) { return a.score > b.score; });
  // The best few again under the player's noise: a safety that fouls half the time is no safety.
  std::optional<Choice> best;
  for (std::size_t k = 0; k < found.size() && k < 3; ++k) {
    double total = 0;
    for (int t = 0; t < 6; ++t) {
      SplitMix64 random(trial_seed(seed_ ^ 0x5afe7ull, static_cast<std::uint64_t>(t)));
      double heading = found[k].heading;
      Stroke s = found[k].stroke;
      apply_noise(noise_, R_, random, heading, s);
      total += safety_value(play(lie, heading, s));
      if (noise_ <= 0) {
        total *= 6;
        break;
      }
    }
    Choice ch = found[k];
    ch.score = total / 6;
    if (!best || ch.score > best->score) best = ch;
  }
  return best;
}

/// A 9-ball push-out: a soft roll that leaves the opponent a shot just under the one worth taking.
std::optional<Choice> Planner::push_out(const std::vector<Ball>& lie) {
  std::optional<Choice> best;
  for (int k = 0; k < 24; ++k)
    for (double speed : {0.7, 1.2}) {
      Stroke s;
      s.speed = speed;
      const Outcome o = play(lie, 15.0 * k, s);
      if (o.scratch || !o.made.empty()) continue;
      const double e = best_ease(o.rest, opponent_targets(o.rest), sigma_play());
      const double value = e < 0.45 ? e : -e;
      if (best && value <= best->score) continue;
      Choice c;
      c.heading = 15.0 * k;
      c.stroke = s;
      c.call.push_out = true;
      c.score = value;
      best = c;
    }
  return best;
}

/// Where to put the cue ball in hand when nothing better is known: the head spot's side of the table.
Vec3 Planner::hand_place() const {
  const bool kitchen = rules_.in_hand == InHand::kitchen;
  for (double x : {-0.7, -0.9, -0.3, 0.0, 0.3})
    for (double y : {0.0, 0.2, -0.2, 0.4, -0.4}) {
      const Vec3 p(x, y, R_);
      if (free_place(table_, p, kitchen)) return p;
    }
  return Vec3(-0.9, 0.0, R_);
}

PlannedShot Planner::planned(const Choice& c) const {
  PlannedShot shot;
  shot.heading_deg = std::fmod(std::fmod(c.heading, 360.0) + 360.0, 360.0);
  shot.stroke = c.stroke;
  shot.place = c.place;
  shot.call = c.call;
  shot.chance = c.call.safety || c.call.push_out ? 0.0 : c.chance;
  shot.simulations = sims_;
  return shot;
}

PlannedShot Planner::plan() {
  if (cue_ < 0) return PlannedShot{};
  if (rules_.break_shot) {
    PlannedShot shot = break_shot();
    shot.simulations = sims_;
    return shot;
  }
  std::vector<Ball> lie = table_;
  std::optional<Vec3> place;
  std::optional<Choice> pot;
  if (rules_.in_hand != InHand::none || lie[static_cast<std::size_t>(cue_)].pocket >= 0) {
    pot = in_hand_pot();
    place = pot && pot->place ? *pot->place : hand_place();
    lie[static_cast<std::size_t>(cue_)].position = *place;
    lie[static_cast<std::size_t>(cue_)].pocket = -1;
  } else {
    pot = best_pot(candidates(lie, std::nullopt));
  }
  if (pot && pot->chance >= kSafetyBelow) return planned(*pot);
  if (rules_.may_push_out)
    if (std::optional<Choice> push = push_out(lie)) return planned(*push);
  std::optional<Choice> safe = safety(lie);
  if (safe && (!pot || safe->score > 1 - pot->chance)) {
    safe->place = place;
    return planned(*safe);
  }
  if (pot) return planned(*pot);
  // Nothing legal found: roll at the first legal ball.
  Choice last;
  last.place = place;
  last.call.safety = true;
  last.stroke.speed = 2.0;
  const int i = rules_.targets.empty() ? -1 : index_of(lie, rules_.targets.front());
  if (i >= 0)
    last.heading = heading_of(lie[static_cast<std::size_t>(i)].position - lie[static_cast<std::size_t>(cue_)].position);
  return planned(last);
}

}  // namespace

PlannedShot plan_shot(const Scene& table, const ShotRules& rules, const PlayerSkill& skill, std::uint64_t seed) {
  return Planner(table, rules, skill, seed).plan();
}

bool take_push_out(const Scene& table, const ShotRules& rules, const PlayerSkill& skill, std::uint64_t seed) {
  return Planner(table, rules, skill, seed).best_pot_chance() >= kTakePushOut;
}

void apply_noise(double noise, double ball_radius, SplitMix64& random, double& heading_deg, Stroke& stroke) {
  if (noise <= 0) return;
  heading_deg += noise * kNoiseHeadingDeg * gaussian(random);
  stroke.elevation_deg = std::clamp(stroke.elevation_deg + noise * kNoiseElevationDeg * gaussian(random), 0.0, 89.0);
  stroke.side += noise * kNoiseOffsetM / ball_radius * gaussian(random);
  stroke.height += noise * kNoiseOffsetM / ball_radius * gaussian(random);
  const double offset = std::hypot(stroke.side, stroke.height);
  const double limit = Stroke::kMiscueOffset * (1 - 1e-9);
  if (offset > limit) {
    stroke.side *= limit / offset;
    stroke.height *= limit / offset;
  }
  stroke.speed = std::clamp(stroke.speed + noise * kNoiseSpeed * gaussian(random), 0.01, Stroke::kMaxSpeed);
}

}  // namespace bsim
