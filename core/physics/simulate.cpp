#include "simulate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <tuple>

#include "check.h"
#include "detect.h"
#include "group.h"
#include "motion.h"
#include "pocket_fall.h"
#include "resolve.h"
#include "strike.h"
#include "timeline.h"

namespace bsim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind { transition, ball_ball, cushion, cushion_end, jaw_face, jaw_round, pocket };

/// A possible next event. It is stale once a ball it involves has changed since it was computed.
struct Candidate {
  double time = 0;
  int rank = 0;  ///< at one instant: transitions, then contacts, then pocket entries
  int a = 0;     ///< the ball (ball-ball: the lower index)
  int b = 0;     ///< the other ball, or ball count + rail index, or the pocket index (jaws: its pocket)
  int end = 0;   ///< cushion_end: 0 for the rail's first end point, 1 for its second; jaws: the jaw
  Kind kind = Kind::transition;
  unsigned version_a = 0, version_b = 0;
  /// rank, a, b and end in one number that orders as they do one after the other (push sets it).
  std::uint64_t order = 0;
};

/// x comes after y: (time, rank, a, b, end) compared in turn, the four integers at once.
struct Later {
  bool operator()(const Candidate& x, const Candidate& y) const {
    return y.time < x.time || (!(x.time < y.time) && y.order < x.order);
  }
};

/// The order of (rank, a, b, end): rank below 4, the others below 2^21 (the constructor makes sure).
std::uint64_t order_of(int rank, int a, int b, int end) {
  return (static_cast<std::uint64_t>(rank) << 62) | (static_cast<std::uint64_t>(a) << 42) |
         (static_cast<std::uint64_t>(b) << 21) | static_cast<std::uint64_t>(end);
}

/// One jaw of a cut pocket (table.h, PocketMouth): its facing, a straight cushion from the rounding into
/// the pocket, and its rounded jaw point, a round one; both answered by the cushion model.
struct Jaw {
  int pocket = -1;
  int rail = -1;  ///< the rail whose end it is (its nose height, its reach)
  Rail face;      ///< playing side on the right of a -> b, as a rail's
  Vec3 round{0, 0, 0};
  double round_radius = 0;
  SweptBox box{};  ///< both, seen from above
};

/// A feature of the table seen from above (a cushion, a jaw, a pocket's circle) for the cheap test of
/// whether a ball's swept box comes within `margin` of its box: `hi` already has the margin added.
struct Reach {
  double lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0, margin = 0;
};
Reach reach_of(const SweptBox& box, double margin) {
  return {box.lo.x(), box.lo.y(), box.hi.x() + margin, box.hi.y() + margin, margin};
}
/// m a ball's swept box is grown by when it is tested against a feature: far beyond the round-off of the
/// box and of the contact (1e-15 m), so a test passes wherever the ball's centre can meet the feature.
constexpr double kBoxSlack = 1e-9;

/// Whether a ball whose centre sweeps `box` can come within a feature's margin of its box: what
/// boxes_within(box, the feature's box, its margin) tests, kBoxSlack looser.
bool within_reach(const SweptBox& box, const Reach& r) {
  return !(box.lo.x() - kBoxSlack > r.hi_x || r.lo_x > box.hi.x() + r.margin + kBoxSlack ||
           box.lo.y() - kBoxSlack > r.hi_y || r.lo_y > box.hi.y() + r.margin + kBoxSlack);
}

/// What the event loop meets of a table, worked out from the scene's rails and pockets and the balls'
/// radius: each cushion's reach and box, the nose lines as the physics meets them (a cut pocket's jaw
/// end stops where its rounding begins) and the cut pockets' jaws.
struct TableGeometry {
  double ball_radius = 0;
  std::vector<Rail> rails;  ///< the scene's, and its pockets: what it was worked out from
  std::vector<Pocket> pockets;
  std::vector<double> reach;
  std::vector<SweptBox> rail_boxes;
  std::vector<Rail> contact_rails;
  std::vector<std::array<char, 2>> rail_end_is_jaw;  ///< a rail end that is a jaw point: its rounding stands for it
  std::vector<Jaw> jaws;
  // For the tests of schedule_own: each rail's and jaw's box within its reach, each pocket's circle, the
  // contact rails' and the jaws' facings' nose lines.
  std::vector<Reach> rail_reach, jaw_reach, pocket_reach;
  std::vector<NoseLine> rail_lines, jaw_lines;
};

void add_jaws(TableGeometry& g, int pocket, const PocketMouth& m) {
  if (!m.cut) return;
  for (int i = 0; i < 2; ++i) {
    const auto r = static_cast<std::size_t>(m.rail[i]);
    const double h = g.rails[r].a.z();
    Jaw jaw;
    jaw.pocket = pocket;
    jaw.rail = m.rail[i];
    jaw.face = m.facing_line(i, h);
    jaw.round = Vec3(m.round_centre[i].x(), m.round_centre[i].y(), h);
    jaw.round_radius = m.round_radius;
    const Vec3 grow(m.round_radius, m.round_radius, 0);
    jaw.box = {jaw.face.a.cwiseMin(jaw.face.b).cwiseMin(jaw.round - grow),
               jaw.face.a.cwiseMax(jaw.face.b).cwiseMax(jaw.round + grow)};
    g.jaws.push_back(jaw);
    (m.at_b[i] ? g.contact_rails[r].b : g.contact_rails[r].a) = Vec3(m.nose_end[i].x(), m.nose_end[i].y(), h);
    g.rail_end_is_jaw[r][m.at_b[i] ? 1 : 0] = 1;
  }
}

std::shared_ptr<const TableGeometry> work_out_table(const Scene& scene) {
  auto g = std::make_shared<TableGeometry>();
  g->ball_radius = scene.physics.ball_radius;
  g->rails = scene.rails;
  g->pockets = scene.pockets;
  for (const Rail& rail : scene.rails) {
    g->reach.push_back(cushion_reach(g->ball_radius, rail.a.z()));
    g->rail_boxes.push_back({rail.a.cwiseMin(rail.b), rail.a.cwiseMax(rail.b)});
  }
  g->contact_rails = scene.rails;
  g->rail_end_is_jaw.assign(scene.rails.size(), {0, 0});
  for (int p = 0; p < static_cast<int>(scene.pockets.size()); ++p)
    add_jaws(*g, p, pocket_mouth(scene.pockets[static_cast<std::size_t>(p)], scene.rails));
  for (std::size_t r = 0; r < g->rails.size(); ++r) {
    g->rail_reach.push_back(reach_of(g->rail_boxes[r], g->reach[r]));
    g->rail_lines.push_back(nose_line(g->contact_rails[r]));
  }
  for (const Jaw& jaw : g->jaws) {
    g->jaw_reach.push_back(reach_of(jaw.box, g->reach[static_cast<std::size_t>(jaw.rail)]));
    g->jaw_lines.push_back(nose_line(jaw.face));
  }
  for (const Pocket& pocket : g->pockets)
    g->pocket_reach.push_back(reach_of({pocket.center, pocket.center}, pocket.radius));
  return g;
}

/// The same bits (so -0 and 0 differ, and a NaN matches itself).
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }
bool same(const Vec3& a, const Vec3& b) { return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z()); }

/// Whether `g` was worked out from this scene's table: every value it depends on is the same to the bit.
bool same_table(const TableGeometry& g, const Scene& scene) {
  if (!same(g.ball_radius, scene.physics.ball_radius) || g.rails.size() != scene.rails.size() ||
      g.pockets.size() != scene.pockets.size())
    return false;
  for (std::size_t r = 0; r < g.rails.size(); ++r)
    if (!same(g.rails[r].a, scene.rails[r].a) || !same(g.rails[r].b, scene.rails[r].b)) return false;
  for (std::size_t p = 0; p < g.pockets.size(); ++p) {
    const Pocket &a = g.pockets[p], &b = scene.pockets[p];
    if (!same(a.center, b.center) || !same(a.radius, b.radius) || a.cut != b.cut || a.kind != b.kind ||
        !same(a.jaw[0], b.jaw[0]) || !same(a.jaw[1], b.jaw[1]) || !same(a.axis, b.axis) ||
        !same(a.jaw_radius, b.jaw_radius))
      return false;
  }
  return true;
}

/// The table's geometry, worked out once for a run of shots on the same table (a player trying strokes
/// simulates thousands): the last one worked out on this thread is kept and used again while its table
/// is the same to the bit, so every shot sees exactly the values it would have worked out itself.
std::shared_ptr<const TableGeometry> table_geometry(const Scene& scene) {
  thread_local std::shared_ptr<const TableGeometry> last;
  if (!last || !same_table(*last, scene)) last = work_out_table(scene);
  return last;
}

/// Each ball's path and the box it sweeps until its next event of its own, cached for the pair tests.
struct Track {
  Path path;  ///< from t0
  double t0 = 0;
  SweptBox box{};    ///< from the last scheduling time to the ball's next event of its own
  bool live = true;  ///< on the bed
};

/// The event loop's working storage: each ball's version, next own event, track and scratch, and the
/// queue of candidates (a heap, kept as std::priority_queue keeps one: std::push_heap, std::pop_heap).
struct Workspace {
  std::vector<unsigned> version;
  std::vector<double> own_time;
  std::vector<Track> tracks;
  std::vector<char> done;
  std::vector<Path> now;
  std::vector<unsigned> now_epoch;
  std::vector<char> in_group;
  std::vector<int> group, changed;
  std::vector<Candidate> queue;
};

/// Storage kept from shot to shot on this thread and lent to one simulation at a time, so that a shot
/// allocates none of its working storage (a player trying strokes simulates thousands of shots). Every
/// shot sets all it reads.
Workspace& spare_storage() {
  thread_local Workspace spare;
  return spare;
}

class Simulator {
 public:
  explicit Simulator(const Scene& scene)
      : scene_(scene),
        params_(scene.physics),
        n_(static_cast<int>(scene.balls.size())),
        table_(table_geometry(scene)),
        reach_(table_->reach),
        rail_boxes_(table_->rail_boxes),
        contact_rails_(table_->contact_rails),
        rail_end_is_jaw_(table_->rail_end_is_jaw),
        jaws_(table_->jaws) {
    const double R = params_.ball_radius;
    const auto n = static_cast<std::size_t>(n_);
    BSIM_EXPECT(n + scene.rails.size() + scene.pockets.size() + jaws_.size() < (1u << 21),
                "fewer than 2^21 balls, rails and pockets: a candidate's order packs them in 21 bits");
    trade_storage();
    segments_.resize(n);
    version_.assign(n, 0);
    own_time_.assign(n, kInf);
    tracks_.assign(n, Track{});
    done_.assign(n, 0);
    now_.resize(n);
    now_epoch_.assign(n, 0);
    in_group_.assign(n, 0);
    queue_.clear();
    for (int i = 0; i < n_; ++i) {
      const Ball& ball = scene.balls[static_cast<std::size_t>(i)];
      BallState s;
      s.position = ball.position;
      s.orientation = ball.orientation;
      if (ball.pocket >= 0) {
        s.motion = Motion::pocketed;  // down since an earlier shot: out of play
        tracks_[static_cast<std::size_t>(i)].live = false;
      } else {
        s.position.z() = R;  // on the bed (the parser allows round-off)
      }
      auto& list = segments_[static_cast<std::size_t>(i)];
      list.reserve(8);
      list.push_back({0.0, s, ball.pocket});
      tracks_[static_cast<std::size_t>(i)].path.p = s.position;
      tracks_[static_cast<std::size_t>(i)].box = {s.position, s.position};
    }
    events_.reserve(16 + n);
  }

  ~Simulator() { trade_storage(); }
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  SimulationResult run() {
    add_event(EventType::start, 0.0, {}, -1, 0.0, Vec3(0, 0, 0), {}, {});
    const double t_cue = kCueLeadTime;
    cap_ = t_cue + kMaxShotTime;
    strike(t_cue);
    long handled = 0;
    while (!queue_.empty()) {
      std::pop_heap(queue_.begin(), queue_.end(), Later{});
      const Candidate c = queue_.back();
      queue_.pop_back();
      if (c.version_a != version(c.a) || (c.kind == Kind::ball_ball && c.version_b != version(c.b))) continue;
      if (++handled > kMaxSteps) {
        cut_off_ = true;  // a safety net: no known scene comes near it
        break;
      }
      handle(c);
    }
    finish(t_cue);
    SimulationResult result;
    result.segments = std::move(segments_);
    result.events = std::move(events_);
    result.drops = std::move(drops_);
    result.candidates_tested = tests_;
    result.groups = groups_;
    result.group_steps = group_steps_;
    result.cut_off = cut_off_;
    result.rest = rest_;
    return result;
  }

 private:
  const Scene& scene_;
  const PhysicsParams& params_;
  int n_;
  double cap_ = kInf;
  std::vector<std::vector<MotionSegment>> segments_;
  std::vector<unsigned> version_;
  std::vector<double> own_time_;  ///< s, each ball's next event of its own: its paths hold until then
  std::vector<Track> tracks_;

  Path path_from(int i, double t) const {
    const Track& track = tracks_[static_cast<std::size_t>(i)];
    const double dt = t - track.t0;
    return {track.path.at(dt), track.path.velocity_at(dt), track.path.a};
  }
  std::shared_ptr<const TableGeometry> table_;
  const std::vector<double>& reach_;
  const std::vector<SweptBox>& rail_boxes_;
  /// The rails' nose lines as the physics meets them: a cut pocket's jaw end stops where its rounding begins.
  const std::vector<Rail>& contact_rails_;
  const std::vector<std::array<char, 2>>& rail_end_is_jaw_;
  const std::vector<Jaw>& jaws_;

  // Scratch, kept from event to event so that handling one allocates nothing of its own.
  std::vector<char> done_;  ///< reschedule: the balls whose pairs are scheduled
  std::vector<Path> now_;   ///< path_now: each ball's path from the time of the current scheduling
  std::vector<unsigned> now_epoch_;
  unsigned epoch_ = 0;      ///< a now_ entry is current while its now_epoch_ equals this
  std::vector<int> group_;  ///< gather_group's answer
  std::vector<char> in_group_;
  std::vector<int> changed_;  ///< resolve_group_event's changed balls
  std::vector<Candidate> queue_;

  /// Swaps the working storage with this thread's spare: borrowed at the start, given back at the end.
  void trade_storage() {
    Workspace& spare = spare_storage();
    version_.swap(spare.version);
    own_time_.swap(spare.own_time);
    tracks_.swap(spare.tracks);
    done_.swap(spare.done);
    now_.swap(spare.now);
    now_epoch_.swap(spare.now_epoch);
    in_group_.swap(spare.in_group);
    group_.swap(spare.group);
    changed_.swap(spare.changed);
    queue_.swap(spare.queue);
  }
  std::vector<Event> events_;
  std::vector<PocketDrop> drops_;
  long tests_ = 0;
  long groups_ = 0, group_steps_ = 0;
  bool cut_off_ = false;
  double rest_ = 0;

  unsigned version(int i) const { return version_[static_cast<std::size_t>(i)]; }
  const MotionSegment& current(int i) const { return segments_[static_cast<std::size_t>(i)].back(); }
  const Rail& rail(int r) const { return scene_.rails[static_cast<std::size_t>(r)]; }
  const Rail& contact_rail(int r) const { return contact_rails_[static_cast<std::size_t>(r)]; }

  BallState state_at(int i, double t) const {
    const MotionSegment& seg = current(i);
    return evolve(seg.start, params_, t - seg.t0);
  }

  void begin_segment(int i, double t, const BallState& s, int pocket = -1) {
    auto& list = segments_[static_cast<std::size_t>(i)];
    if (list.back().t0 == t)
      list.back() = {t, s, pocket};  // several changes at one instant: keep the last
    else
      list.push_back({t, s, pocket});
    ++version_[static_cast<std::size_t>(i)];
  }

  void add_event(EventType type, double t, std::vector<int> balls, int rail, double speed, const Vec3& where,
                 std::vector<BallState> before, std::vector<BallState> after) {
    Event e;
    e.index = static_cast<int>(events_.size());
    e.time = t;
    e.type = type;
    e.balls = std::move(balls);
    e.rail = rail;
    e.speed = speed;
    e.where = where;
    e.before = std::move(before);
    e.after = std::move(after);
    events_.push_back(std::move(e));
  }

  /// A pair resolved alone: a ball-ball event with its one contact (the event's own time, speed and point).
  void add_pair_event(int i, int j, double t, double speed, const Vec3& where, std::vector<BallState> before,
                      std::vector<BallState> after) {
    add_event(EventType::ball_ball, t, {i, j}, -1, speed, where, std::move(before), std::move(after));
    events_.back().contacts = {{i, j, t, speed, where}};
  }

  /// The cue impact: every ball on the bed takes its line's velocity and spin, the struck one the
  /// stroke's when the cue has one (strike.h; the same as strike_cue_ball gives the scene).
  void strike(double t) {
    const Cue& cue = scene_.cue();
    const int target = cue.target;
    std::vector<int> changed;
    for (int i = 0; i < n_; ++i) {
      const Ball& ball = scene_.balls[static_cast<std::size_t>(i)];
      if (ball.pocket >= 0) continue;
      BallState s = current(i).start;
      s.velocity = ball.velocity;
      s.spin = ball.spin;
      if (i == target && cue.stroke) {
        const StrikeResult struck = bsim::strike(*cue.stroke, cue.heading_deg, params_);
        s.velocity = struck.velocity;
        s.spin = struck.spin;
      }
      s = classify(s, params_);
      const bool over_pocket = std::any_of(scene_.pockets.begin(), scene_.pockets.end(), [&](const Pocket& p) {
        return Vec3(s.position.x() - p.center.x(), s.position.y() - p.center.y(), 0).norm() < p.radius;
      });
      if (i == target) add_event(EventType::cue, t, {i}, -1, s.velocity.norm(), s.position, {current(i).start}, {s});
      if (s.motion != Motion::stationary) begin_segment(i, t, s);
      if (s.motion != Motion::stationary || over_pocket) changed.push_back(i);
    }
    reschedule(changed, t);
  }

  void reschedule(std::span<const int> changed, double t) {
    for (int i : changed) schedule_own(i, t);
    ++epoch_;
    for (int i : changed) {
      for (int j = 0; j < n_; ++j)
        if (j != i && !done_[static_cast<std::size_t>(j)]) schedule_pair(std::min(i, j), std::max(i, j), t);
      done_[static_cast<std::size_t>(i)] = 1;
    }
    for (int i : changed) done_[static_cast<std::size_t>(i)] = 0;
  }
  void reschedule(std::initializer_list<int> changed, double t) {
    reschedule(std::span<const int>(changed.begin(), changed.size()), t);
  }

  /// path_from(i, t) at the time of the current scheduling (epoch_), worked out once for all its pairs.
  const Path& path_now(int i, double t) {
    const auto k = static_cast<std::size_t>(i);
    if (now_epoch_[k] != epoch_) {
      now_[k] = path_from(i, t);
      now_epoch_[k] = epoch_;
    }
    return now_[k];
  }

  /// Queues c, with the versions of its balls now: std::push_heap's sift-up, step for step (so the
  /// heap is the same), with c written once, member by member, into the place it ends in (a copy of c
  /// whole, just written member by member, would wait on the processor's store forwarding).
  void push(const Candidate& candidate) {
    Candidate c = candidate;
    c.order = order_of(c.rank, c.a, c.b, c.end);
    std::size_t hole = queue_.size();
    queue_.emplace_back();
    while (hole > 0) {
      const std::size_t parent = (hole - 1) / 2;
      if (!Later{}(queue_[parent], c)) break;
      queue_[hole] = queue_[parent];
      hole = parent;
    }
    Candidate& d = queue_[hole];
    d.time = c.time;
    d.rank = c.rank;
    d.a = c.a;
    d.b = c.b;
    d.end = c.end;
    d.order = c.order;
    d.kind = c.kind;
    d.version_a = version(c.a);
    d.version_b = c.kind == Kind::ball_ball ? version(c.b) : c.version_b;
  }

  /// The ball's next transition, cushion contact or pocket entry.
  void schedule_own(int i, double t) {
    const MotionSegment& seg = current(i);
    Track& track = tracks_[static_cast<std::size_t>(i)];
    track.t0 = seg.t0;
    track.path = path_of(seg.start, params_);
    track.live = on_bed(seg.start);
    own_time_[static_cast<std::size_t>(i)] = kInf;
    if (!track.live) return;
    const double transition = seg.t0 + transition_time(seg.start, params_) - t;
    double horizon = std::min(transition, cap_ - t);
    Candidate best;
    best.a = i;
    bool found = false;
    if (transition <= horizon && std::isfinite(transition)) {
      best.time = transition;
      best.kind = Kind::transition;
      found = true;
    }
    const Path path = path_from(i, t);
    // The box the centre sweeps until the horizon, which shrinks to each earlier event found: a feature
    // it cannot reach in that time has no event before the one found, so it is not tested.
    SweptBox box = swept_box(path, horizon);
    auto consider = [&](std::optional<double> dt, Kind kind, int rank, int b, int end) {
      ++tests_;
      if (!dt || (found && *dt >= best.time)) return;
      best.time = *dt;
      best.kind = kind;
      best.rank = rank;
      best.b = b;
      best.end = end;
      horizon = *dt;
      found = true;
      box = swept_box(path, horizon);
    };
    const TableGeometry& table = *table_;
    if (path.moves()) {
      for (std::size_t r = 0; r < table.rails.size(); ++r) {
        if (!within_reach(box, table.rail_reach[r])) continue;
        const double reach = table.reach[r];
        const int b = n_ + static_cast<int>(r);
        consider(next_ball_cushion(path, table.rail_lines[r], reach, horizon), Kind::cushion, 1, b, 0);
        const auto& jawed = table.rail_end_is_jaw[r];
        if (!jawed[0]) consider(next_ball_point(path, table.rails[r].a, reach, horizon), Kind::cushion_end, 1, b, 0);
        if (!jawed[1]) consider(next_ball_point(path, table.rails[r].b, reach, horizon), Kind::cushion_end, 1, b, 1);
      }
      for (std::size_t j = 0; j < table.jaws.size(); ++j) {
        if (!within_reach(box, table.jaw_reach[j])) continue;
        const Jaw& jaw = table.jaws[j];
        const double reach = table.reach[static_cast<std::size_t>(jaw.rail)];
        const int k = static_cast<int>(j);
        consider(next_ball_cushion(path, table.jaw_lines[j], reach, horizon), Kind::jaw_face, 1, jaw.pocket, k);
        consider(next_ball_point(path, jaw.round, reach + jaw.round_radius, horizon), Kind::jaw_round, 1, jaw.pocket,
                 k);
      }
    }
    // Pockets even for a ball at rest: one left over a hole drops.
    for (std::size_t p = 0; p < table.pockets.size(); ++p) {
      if (!within_reach(box, table.pocket_reach[p])) continue;
      consider(next_pocket_entry(path, table.pockets[p], horizon), Kind::pocket, 2, static_cast<int>(p), 0);
    }
    if (found) horizon = best.time;
    own_time_[static_cast<std::size_t>(i)] = t + horizon;
    track.box = box;  // swept_box(path, horizon): the last found, or the first if none
    if (!found) return;
    best.time += t;
    push(best);
  }

  void schedule_pair(int i, int j, double t) {
    const Track &ti = tracks_[static_cast<std::size_t>(i)], &tj = tracks_[static_cast<std::size_t>(j)];
    if (!ti.live || !tj.live || (!ti.path.moves() && !tj.path.moves())) return;
    const double distance = 2 * params_.ball_radius;
    if (!boxes_within(ti.box, tj.box, distance)) return;
    const double horizon = std::min(own_time_[static_cast<std::size_t>(i)], own_time_[static_cast<std::size_t>(j)]) - t;
    ++tests_;
    const std::optional<double> dt = next_ball_ball(path_now(i, t), path_now(j, t), distance, horizon);
    if (!dt) return;
    Candidate c;
    c.time = t + *dt;
    c.rank = 1;
    c.a = i;
    c.b = j;
    c.kind = Kind::ball_ball;
    push(c);
  }

  /// Moves two overlapping balls apart along their line of centres to touching. Only a push
  /// (detect.h) lets balls overlap, by at most kMaxPushOverlap, so this moves them by a micrometre at most.
  void separate(BallState& a, BallState& b) const {
    Vec3 n(b.position.x() - a.position.x(), b.position.y() - a.position.y(), 0);
    const double touching = 2 * params_.ball_radius;
    // Farther than touching by a part in 1e9 (far beyond round-off): no overlap, as the norm would find.
    if (n.x() * n.x() + n.y() * n.y() > touching * touching * (1 + 1e-9)) return;
    const double d = n.norm(), overlap = touching - d;
    if (!(overlap > 0) || d == 0) return;
    n /= d;
    a.position -= 0.5 * overlap * n;
    b.position += 0.5 * overlap * n;
  }

  /// A gentle contact after which the two would at once press together again (one ball pushing
  /// another) is resolved without bounce, so a push is a short train of contacts, not an endless
  /// series of ever smaller bounces.
  std::pair<BallState, BallState> resolve_pair(const BallState& a, const BallState& b, double speed) const {
    if (speed < kPushSpeed) {
      auto result = resolve_push(a, b, params_);
      const Path pa = path_of(result.first, params_), pb = path_of(result.second, params_);
      const Vec3 c = pb.p - pa.p, v = pb.v - pa.v, acc = 0.5 * (pb.a - pa.a);
      const double curvature = v.x() * v.x() + v.y() * v.y() + 2 * (acc.x() * c.x() + acc.y() * c.y());
      if (curvature < 0) return result;
    }
    return resolve_ball_ball(a, b, params_);
  }

  /// The balls a contact of a and b closing at `speed` resolves together: a and b, and every ball on the
  /// bed within group_gap(speed) of one already in, in ascending order (in group_). Just a and b when
  /// they are alone.
  const std::vector<int>& gather_group(int a, int b, double t, double speed) {
    const double reach = 2 * params_.ball_radius + group_gap(speed, params_);
    ++epoch_;
    group_.assign({a, b});
    in_group_[static_cast<std::size_t>(a)] = in_group_[static_cast<std::size_t>(b)] = 1;
    for (std::size_t k = 0; k < group_.size(); ++k) {
      const Vec3 p = path_now(group_[k], t).p;
      for (int j = 0; j < n_; ++j) {
        if (in_group_[static_cast<std::size_t>(j)] || !tracks_[static_cast<std::size_t>(j)].live) continue;
        const Vec3& q = path_now(j, t).p;
        if (within(q.x() - p.x(), q.y() - p.y(), reach)) {
          in_group_[static_cast<std::size_t>(j)] = 1;
          group_.push_back(j);
        }
      }
    }
    for (int i : group_) in_group_[static_cast<std::size_t>(i)] = 0;
    std::sort(group_.begin(), group_.end());
    return group_;
  }

  /// std::hypot(dx, dy) < reach, with hypot only where the squares lie within a part in 1e9 of the
  /// boundary (hypot errs by under an ulp, the squares by a few: elsewhere both give the same answer).
  static bool within(double dx, double dy, double reach) {
    const double d2 = dx * dx + dy * dy, r2 = reach * reach;
    if (d2 > r2 * (1 + 1e-9)) return false;
    if (d2 < r2 * (1 - 1e-9)) return true;
    return std::hypot(dx, dy) < reach;
  }

  /// Several balls in contact at once (group.h): resolved together as one numbered event listing every
  /// ball that took part and each contact.
  void resolve_group_event(const std::vector<int>& group, int trigger_a, int trigger_b, double t) {
    std::vector<BallState> before;
    for (int i : group) before.push_back(state_at(i, t));
    // Back to touching where a push left two balls pressed together (by a micrometre at most).
    for (std::size_t p = 0; p < before.size(); ++p)
      for (std::size_t q = p + 1; q < before.size(); ++q) separate(before[p], before[q]);
    const GroupResult result = resolve_group(before, params_);
    ++groups_;
    group_steps_ += result.steps;

    std::vector<int> balls;
    std::vector<BallState> was, now;
    changed_.clear();
    for (std::size_t k = 0; k < group.size(); ++k) {
      const int i = group[k];
      if (result.touched[k]) {
        balls.push_back(i);
        was.push_back(before[k]);
        now.push_back(result.after[k]);
      }
      // A ball only moved back to touching starts a segment too (its velocity unchanged).
      if (result.touched[k] || before[k].position != state_at(i, t).position) {
        begin_segment(i, t, result.after[k]);
        changed_.push_back(i);
      }
    }
    std::vector<Contact> contacts;
    double speed = 0;
    Vec3 where(0, 0, 0);
    for (const GroupContact& contact : result.contacts) {
      const int i = group[static_cast<std::size_t>(contact.a)], j = group[static_cast<std::size_t>(contact.b)];
      const BallState &a = before[static_cast<std::size_t>(contact.a)],
                      &b = before[static_cast<std::size_t>(contact.b)];
      const Vec3 n = Vec3(b.position.x() - a.position.x(), b.position.y() - a.position.y(), 0).normalized();
      const Vec3 point = a.position + params_.ball_radius * n;
      if ((i == trigger_a && j == trigger_b) || speed == 0) where = point;
      speed = std::max(speed, contact.speed);
      contacts.push_back({i, j, t + contact.time, contact.speed, point});
    }
    add_event(EventType::ball_ball, t, balls, -1, speed, where, std::move(was), std::move(now));
    events_.back().contacts = std::move(contacts);
    events_.back().grouped = true;
    reschedule(changed_, t);
  }

  BallState resolve_cushion(const BallState& s, const Vec3& toward, double h) const {
    if (cushion_closing_speed(s, toward, h, params_) < kPushSpeed) {
      PhysicsParams plastic = params_;
      plastic.e_rail = 0;
      const BallState result = resolve_ball_cushion(s, toward, h, plastic);
      if (path_of(result, params_).a.dot(toward) > 0) return result;  // it presses on into the cushion
    }
    return resolve_ball_cushion(s, toward, h, params_);
  }

  void handle(const Candidate& c) {
    switch (c.kind) {
      case Kind::transition:
        begin_segment(c.a, c.time, after_transition(current(c.a).start, params_));
        reschedule({c.a}, c.time);
        return;
      case Kind::ball_ball: handle_ball_ball(c); return;
      case Kind::cushion:
      case Kind::cushion_end: handle_cushion(c); return;
      case Kind::jaw_face:
      case Kind::jaw_round: handle_jaw(c); return;
      case Kind::pocket: handle_pocket(c); return;
    }
    BSIM_EXPECT(false, "an event candidate of no known kind");
  }

  /// Two balls meet: resolved as a pair, or with the balls touching them as a group (group.h).
  void handle_ball_ball(const Candidate& c) {
    const double t = c.time;
    BallState a = state_at(c.a, t), b = state_at(c.b, t);
    const double speed = closing_speed(a, b);
    if (!(speed > 0)) {
      // A resting contact that did not press after all: nothing to resolve.
      ++epoch_;
      schedule_pair(c.a, c.b, t);
      return;
    }
    if (speed >= kMinEventSpeed) {
      const std::vector<int>& group = gather_group(c.a, c.b, t, speed);
      if (group.size() > 2) {
        resolve_group_event(group, c.a, c.b, t);
        return;
      }
    }
    separate(a, b);
    const auto [na, nb] = resolve_pair(a, b, speed);
    const Vec3 n = Vec3(b.position.x() - a.position.x(), b.position.y() - a.position.y(), 0).normalized();
    if (speed >= kMinEventSpeed)
      add_pair_event(c.a, c.b, t, speed, a.position + params_.ball_radius * n, {a, b}, {na, nb});
    begin_segment(c.a, t, na);
    begin_segment(c.b, t, nb);
    reschedule({c.a, c.b}, t);
  }

  /// A ball meets a cushion's nose line (Kind::cushion) or one of its ends (Kind::cushion_end).
  void handle_cushion(const Candidate& c) {
    const double t = c.time;
    const int r = c.b - n_;
    const Rail& cushion = rail(r);
    const BallState s = state_at(c.a, t);
    const double reach = reach_[static_cast<std::size_t>(r)];
    const auto [toward, overlap] = c.kind == Kind::cushion
                                       ? line_contact(s, cushion, reach)
                                       : point_contact(s, c.end == 0 ? cushion.a : cushion.b, reach);
    bounce(c.a, t, s, toward, overlap, cushion.a.z(), EventType::ball_rail, r, -1);
  }

  /// A ball meets a cut pocket's facing (Kind::jaw_face) or rounded jaw point (Kind::jaw_round): the
  /// cushion model answers it as it answers a rail, and it is a ball-jaw event of that pocket.
  void handle_jaw(const Candidate& c) {
    const double t = c.time;
    const Jaw& jaw = jaws_[static_cast<std::size_t>(c.end)];
    const BallState s = state_at(c.a, t);
    const double reach = reach_[static_cast<std::size_t>(jaw.rail)];
    const auto [toward, overlap] = c.kind == Kind::jaw_face ? line_contact(s, jaw.face, reach)
                                                            : point_contact(s, jaw.round, reach + jaw.round_radius);
    bounce(c.a, t, s, toward, overlap, jaw.face.a.z(), EventType::ball_jaw, jaw.rail, jaw.pocket);
  }

  /// The unit normal from the ball's centre towards a nose line, and how far the ball overlaps it.
  static std::pair<Vec3, double> line_contact(const BallState& s, const Rail& line, double reach) {
    const Vec3 dir = Vec3(line.b.x() - line.a.x(), line.b.y() - line.a.y(), 0).normalized();
    const Vec3 toward(-dir.y(), dir.x(), 0);
    return {toward, reach + toward.dot(Vec3(s.position.x() - line.a.x(), s.position.y() - line.a.y(), 0))};
  }

  /// The same towards a point (a cushion's end, a jaw's rounding) whose surface is `reach` from the centre.
  static std::pair<Vec3, double> point_contact(const BallState& s, const Vec3& point, double reach) {
    const Vec3 to(point.x() - s.position.x(), point.y() - s.position.y(), 0);
    return {to.normalized(), reach - to.norm()};
  }

  /// The ball touching a cushion (a rail or a jaw) bounces off it by the cushion model; a numbered event
  /// when it closes fast enough to be heard.
  void bounce(int i, double t, BallState s, const Vec3& toward, double overlap, double h, EventType type, int r,
              int pocket) {
    const double speed = cushion_closing_speed(s, toward, h, params_);
    if (!(speed > 0)) {
      schedule_own(i, t);
      return;
    }
    if (overlap > 0) s.position -= overlap * toward;  // back to touching (see separate())
    const BallState ns = resolve_cushion(s, toward, h);
    if (speed >= kMinEventSpeed) {
      add_event(type, t, {i}, r, speed, cushion_contact_point(s, toward, h, params_), {s}, {ns});
      events_.back().pocket = pocket;
    }
    begin_segment(i, t, ns);
    reschedule({i}, t);
  }

  /// A ball's centre crosses a pocket's drop circle: it falls and comes to rest in the pocket.
  void handle_pocket(const Candidate& c) {
    const double t = c.time;
    const Pocket& pocket = scene_.pockets[static_cast<std::size_t>(c.b)];
    BallState s = state_at(c.a, t);
    s.motion = Motion::falling;
    begin_segment(c.a, t, s, c.b);
    const FallEnd end = fall_end(s, pocket, params_);
    const double fall = end.duration;
    BallState rest = end.state;
    rest.velocity.setZero();
    rest.spin.setZero();
    rest.motion = Motion::pocketed;
    segments_[static_cast<std::size_t>(c.a)].push_back({t + fall, rest, c.b});
    drops_.push_back({t, c.a, c.b});
    own_time_[static_cast<std::size_t>(c.a)] = kInf;
    tracks_[static_cast<std::size_t>(c.a)].live = false;
  }

  void finish(double t_cue) {
    double settled = t_cue;
    for (int i = 0; i < n_; ++i) {
      const MotionSegment& seg = current(i);
      if (!cut_off_ && (seg.start.motion == Motion::stationary || seg.start.motion == Motion::pocketed)) {
        settled = std::max(settled, seg.t0);
      } else {
        // Still moving: stop the shot where the simulation stopped.
        settled = std::max(settled, cut_off_ ? seg.t0 : cap_);
        cut_off_ = true;
      }
    }
    rest_ = settled;
    const double end = shot_end(settled);
    add_event(EventType::end, end, {}, -1, 0.0, Vec3(0, 0, 0), {}, {});
  }
};

}  // namespace

double shot_end(double rest) { return std::ceil((rest + kEndHold) / kDurationStep) * kDurationStep; }

SimulationResult simulate_events(const Scene& scene) { return Simulator(scene).run(); }

}  // namespace bsim
