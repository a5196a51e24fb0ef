#include "simulate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>

#include "constants.h"
#include "detect.h"
#include "motion.h"
#include "pocket_fall.h"
#include "resolve.h"

namespace bsim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind { transition, ball_ball, cushion, cushion_end, pocket };

/// A possible next event. It is stale once a ball it involves has changed since it was computed.
struct Candidate {
  double time = 0;
  int rank = 0;  ///< at one instant: transitions, then contacts, then pocket entries
  int a = 0;     ///< the ball (ball-ball: the lower index)
  int b = 0;     ///< the other ball, or ball count + rail index, or the pocket index
  int end = 0;   ///< cushion_end: 0 for the rail's first end point, 1 for its second
  Kind kind = Kind::transition;
  unsigned version_a = 0, version_b = 0;

  auto key() const { return std::tie(time, rank, a, b, end); }
};

struct Later {
  bool operator()(const Candidate& x, const Candidate& y) const { return x.key() > y.key(); }
};

bool on_bed(const BallState& s) { return s.motion != Motion::falling && s.motion != Motion::pocketed; }

class Simulator {
 public:
  explicit Simulator(const Scene& scene) : scene_(scene), params_(scene.physics), n_(static_cast<int>(scene.balls.size())) {
    const double R = params_.ball_radius;
    segments_.resize(static_cast<std::size_t>(n_));
    version_.assign(static_cast<std::size_t>(n_), 0);
    own_time_.assign(static_cast<std::size_t>(n_), kInf);
    for (int i = 0; i < n_; ++i) {
      const Ball& ball = scene.balls[static_cast<std::size_t>(i)];
      BallState s;
      s.position = ball.position;
      s.orientation = ball.orientation;
      segments_[static_cast<std::size_t>(i)].push_back({0.0, s, -1});
    }
    for (const Rail& rail : scene.rails) {
      reach_.push_back(cushion_reach(R, rail.a.z()));
      rail_boxes_.push_back({rail.a.cwiseMin(rail.b), rail.a.cwiseMax(rail.b)});
    }
  }

  SimulationResult run() {
    add_event(EventType::start, 0.0, {}, -1, 0.0, Vec3(0, 0, 0), {}, {});
    const double t_cue = kCueLeadTime;
    cap_ = t_cue + kMaxShotTime;
    strike(t_cue);
    while (!queue_.empty()) {
      const Candidate c = queue_.top();
      queue_.pop();
      if (c.version_a != version(c.a) || (c.kind == Kind::ball_ball && c.version_b != version(c.b))) continue;
      handle(c);
    }
    finish(t_cue);
    SimulationResult result;
    result.segments = std::move(segments_);
    result.events = std::move(events_);
    result.drops = std::move(drops_);
    result.candidates_tested = tests_;
    result.cut_off = cut_off_;
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
  std::vector<double> reach_;
  std::vector<SweptBox> rail_boxes_;
  std::priority_queue<Candidate, std::vector<Candidate>, Later> queue_;
  std::vector<Event> events_;
  std::vector<PocketDrop> drops_;
  long tests_ = 0;
  bool cut_off_ = false;

  unsigned version(int i) const { return version_[static_cast<std::size_t>(i)]; }
  const MotionSegment& current(int i) const { return segments_[static_cast<std::size_t>(i)].back(); }
  const Rail& rail(int r) const { return scene_.rails[static_cast<std::size_t>(r)]; }

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

  /// The cue impact: every ball takes its line's velocity and spin.
  void strike(double t) {
    const int target = scene_.cue.target;
    std::vector<int> changed;
    for (int i = 0; i < n_; ++i) {
      const Ball& ball = scene_.balls[static_cast<std::size_t>(i)];
      BallState s = current(i).start;
      s.velocity = ball.velocity;
      s.spin = ball.spin;
      s = classify(s, params_);
      if (i == target)
        add_event(EventType::cue, t, {i}, -1, s.velocity.norm(), s.position, {current(i).start}, {s});
      if (s.motion != Motion::stationary) {
        begin_segment(i, t, s);
        changed.push_back(i);
      }
    }
    reschedule(changed, t);
  }

  void reschedule(const std::vector<int>& changed, double t) {
    for (int i : changed) schedule_own(i, t);
    for (std::size_t k = 0; k < changed.size(); ++k) {
      const int i = changed[k];
      for (int j = 0; j < n_; ++j) {
        if (j == i) continue;
        const bool done = std::find(changed.begin(), changed.begin() + static_cast<long>(k), j) !=
                          changed.begin() + static_cast<long>(k);
        if (!done) schedule_pair(std::min(i, j), std::max(i, j), t);
      }
    }
  }

  void push(Candidate c) {
    c.version_a = version(c.a);
    if (c.kind == Kind::ball_ball) c.version_b = version(c.b);
    queue_.push(c);
  }

  /// The ball's next transition, cushion contact or pocket entry.
  void schedule_own(int i, double t) {
    own_time_[static_cast<std::size_t>(i)] = kInf;
    const BallState s = state_at(i, t);
    if (!on_bed(s)) return;
    const double transition = transition_time(s, params_);
    double horizon = std::min(transition, cap_ - t);
    own_time_[static_cast<std::size_t>(i)] = t + horizon;
    Candidate best;
    best.a = i;
    bool found = false;
    if (transition <= horizon && std::isfinite(transition)) {
      best.time = transition;
      best.kind = Kind::transition;
      found = true;
    }
    const Path path = path_of(s, params_);
    if (path.moves()) {
      const SweptBox box = swept_box(path, horizon);
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
      };
      for (int r = 0; r < static_cast<int>(scene_.rails.size()); ++r) {
        const double reach = reach_[static_cast<std::size_t>(r)];
        if (!boxes_within(box, rail_boxes_[static_cast<std::size_t>(r)], reach)) continue;
        consider(next_ball_cushion(path, rail(r), reach, horizon), Kind::cushion, 1, n_ + r, 0);
        consider(next_ball_point(path, rail(r).a, reach, horizon), Kind::cushion_end, 1, n_ + r, 0);
        consider(next_ball_point(path, rail(r).b, reach, horizon), Kind::cushion_end, 1, n_ + r, 1);
      }
      for (int p = 0; p < static_cast<int>(scene_.pockets.size()); ++p) {
        const Pocket& pocket = scene_.pockets[static_cast<std::size_t>(p)];
        if (!boxes_within(box, {pocket.center, pocket.center}, pocket.radius)) continue;
        consider(next_pocket_entry(path, pocket, horizon), Kind::pocket, 2, p, 0);
      }
    }
    if (!found) return;
    own_time_[static_cast<std::size_t>(i)] = t + best.time;
    best.time += t;
    push(best);
  }

  void schedule_pair(int i, int j, double t) {
    const BallState si = state_at(i, t), sj = state_at(j, t);
    if (!on_bed(si) || !on_bed(sj)) return;
    const Path pi = path_of(si, params_), pj = path_of(sj, params_);
    if (!pi.moves() && !pj.moves()) return;
    const double horizon = std::min(own_time_[static_cast<std::size_t>(i)], own_time_[static_cast<std::size_t>(j)]) - t;
    const double distance = 2 * params_.ball_radius;
    if (!boxes_within(swept_box(pi, horizon), swept_box(pj, horizon), distance)) return;
    ++tests_;
    const std::optional<double> dt = next_ball_ball(pi, pj, distance, horizon);
    if (!dt) return;
    Candidate c;
    c.time = t + *dt;
    c.rank = 1;
    c.a = i;
    c.b = j;
    c.kind = Kind::ball_ball;
    push(c);
  }

  void handle(const Candidate& c) {
    const double t = c.time;
    switch (c.kind) {
      case Kind::transition: {
        begin_segment(c.a, t, after_transition(current(c.a).start, params_));
        reschedule({c.a}, t);
        break;
      }
      case Kind::ball_ball: {
        const BallState a = state_at(c.a, t), b = state_at(c.b, t);
        const auto [na, nb] = resolve_ball_ball(a, b, params_);
        const Vec3 n = Vec3(b.position.x() - a.position.x(), b.position.y() - a.position.y(), 0).normalized();
        add_event(EventType::ball_ball, t, {c.a, c.b}, -1, closing_speed(a, b),
                  a.position + params_.ball_radius * n, {a, b}, {na, nb});
        begin_segment(c.a, t, na);
        begin_segment(c.b, t, nb);
        reschedule({c.a, c.b}, t);
        break;
      }
      case Kind::cushion:
      case Kind::cushion_end: {
        const int r = c.b - n_;
        const Rail& cushion = rail(r);
        const BallState s = state_at(c.a, t);
        Vec3 toward;
        if (c.kind == Kind::cushion) {
          const Vec3 dir = Vec3(cushion.b.x() - cushion.a.x(), cushion.b.y() - cushion.a.y(), 0).normalized();
          toward = Vec3(-dir.y(), dir.x(), 0);
        } else {
          const Vec3& point = c.end == 0 ? cushion.a : cushion.b;
          toward = Vec3(point.x() - s.position.x(), point.y() - s.position.y(), 0).normalized();
        }
        const double h = cushion.a.z();
        const BallState ns = resolve_ball_cushion(s, toward, h, params_);
        add_event(EventType::ball_rail, t, {c.a}, r, cushion_closing_speed(s, toward, h, params_),
                  cushion_contact_point(s, toward, h, params_), {s}, {ns});
        begin_segment(c.a, t, ns);
        reschedule({c.a}, t);
        break;
      }
      case Kind::pocket: {
        const Pocket& pocket = scene_.pockets[static_cast<std::size_t>(c.b)];
        BallState s = state_at(c.a, t);
        s.motion = Motion::falling;
        begin_segment(c.a, t, s, c.b);
        const double fall = fall_duration(s, pocket, params_);
        BallState rest = fall_state(s, pocket, params_, fall);
        rest.velocity.setZero();
        rest.spin.setZero();
        rest.motion = Motion::pocketed;
        segments_[static_cast<std::size_t>(c.a)].push_back({t + fall, rest, c.b});
        drops_.push_back({t, c.a, c.b});
        own_time_[static_cast<std::size_t>(c.a)] = kInf;
        break;
      }
    }
  }

  void finish(double t_cue) {
    double settled = t_cue;
    for (int i = 0; i < n_; ++i) {
      const MotionSegment& seg = current(i);
      if (seg.start.motion == Motion::stationary || seg.start.motion == Motion::pocketed) {
        settled = std::max(settled, seg.t0);
      } else {
        settled = std::max(settled, cap_);
        cut_off_ = true;
      }
    }
    const double end = std::ceil((settled + kEndHold) / kDurationStep) * kDurationStep;
    add_event(EventType::end, end, {}, -1, 0.0, Vec3(0, 0, 0), {}, {});
  }
};

}  // namespace

SimulationResult simulate_events(const Scene& scene) { return Simulator(scene).run(); }

Timeline simulate(const Scene& scene) {
  SimulationResult result = simulate_events(scene);
  return Timeline(scene, std::move(result.segments), std::move(result.events), std::move(result.drops));
}

}  // namespace bsim
