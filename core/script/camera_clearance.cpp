#include "camera_clearance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "table.h"

namespace bsim {

namespace {

/// What the camera can be inside: the table, the floor, the lamp, then one kind per ball.
enum Kind { kTable = 0, kFloor = 1, kLamp = 2, kFirstBall = 3 };

/// s to which a span's ends are found between two samples.
constexpr double kEdgeTolerance = 1e-4;

bool over(const TableRect& r, const Vec3& p) {
  return p.x() >= r.x0 && p.x() <= r.x1 && p.y() >= r.y0 && p.y() <= r.y1;
}

std::string fixed(double value, int digits) {
  if (std::abs(value) < 0.5 * std::pow(10.0, -digits)) value = 0.0;  // no "-0.00"
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

/// The camera at one instant: where it is, which description is in charge, how far each ball is.
struct Sample {
  double t = 0;
  int shot = 0;  ///< the description in charge: the one being blended into, or the one that holds
  bool blending = false;
  Vec3 location{0, 0, 0};
  std::vector<double> ball_distance;  ///< m from each ball's centre (infinity for a ball out of sight)
};

class Checker {
 public:
  Checker(const Scene& scene, const Timeline& timeline, const CameraScript& camera)
      : scene_(scene), timeline_(timeline), camera_(camera), layout_(table_layout(scene)) {}

  Sample sample(double t) const {
    Sample s;
    s.t = t;
    s.shot = -1;
    for (const CameraWindow& window : camera_.windows()) {
      if (window.end > window.begin && t >= window.begin && t <= window.end) {
        s.shot = window.shot;
        s.blending = true;
        break;
      }
    }
    if (s.shot < 0) s.shot = camera_.shot_at(t);
    s.location = camera_.pose(t).location;
    const double radius = scene_.physics.ball_radius;
    for (int ball = 0; ball < timeline_.ball_count(); ++ball) {
      const Vec3 centre = timeline_.motion_state(ball, t).position;
      const bool hidden = centre.z() < -radius;  // sunk into a pocket, out of sight
      s.ball_distance.push_back(hidden ? std::numeric_limits<double>::infinity() : (s.location - centre).norm());
    }
    return s;
  }

  /// How bad sample `s` is for `kind`: a value the span's worst is taken from (lower is worse), or
  /// nullopt when the camera is clear of it.
  std::optional<double> trouble(int kind, const Sample& s) const {
    const Vec3& p = s.location;
    const bool over_table = over(layout_.wood_outer, p);
    switch (kind) {
      case kTable:
        if (over_table && p.z() <= layout_.rail_top) return p.z();
        return std::nullopt;
      case kFloor:
        if (!over_table && p.z() <= layout_.floor) return p.z();
        return std::nullopt;
      case kLamp:
        if (over(layout_.lamp, p) && p.z() >= layout_.lamp_bottom && p.z() <= layout_.lamp_top) return 0.0;
        return std::nullopt;
      default: {
        const double d = s.ball_distance[static_cast<std::size_t>(kind - kFirstBall)];
        if (d < ball_clearance()) return d;
        return std::nullopt;
      }
    }
  }

  /// The description in charge at t when the camera is in trouble of `kind` then, else -1.
  int state(int kind, const Sample& s) const { return trouble(kind, s) ? s.shot : -1; }

  /// The first instant in (clear, bad] at which the state is `shot`, bad's state being `shot`.
  double edge(int kind, int shot, double clear, double bad) const {
    while (std::abs(bad - clear) > kEdgeTolerance) {
      const double mid = 0.5 * (clear + bad);
      (state(kind, sample(mid)) == shot ? bad : clear) = mid;
    }
    return bad;
  }

  double ball_clearance() const { return scene_.physics.ball_radius + kCameraBallClearance; }
  const TableLayout& layout() const { return layout_; }

 private:
  const Scene& scene_;
  const Timeline& timeline_;
  const CameraScript& camera_;
  TableLayout layout_;
};

struct Span {
  int shot = 0;
  double begin = 0, end = 0;
  double worst = 0;
  int samples = 0, blending = 0;
};

std::string message(int kind, const Span& span, const Checker& checker) {
  const TableLayout& layout = checker.layout();
  std::string when = span.end - span.begin < 0.005
                         ? "at " + fixed(span.begin, 2) + " s"
                         : "from " + fixed(span.begin, 2) + " s to " + fixed(span.end, 2) + " s";
  if (span.blending == span.samples) {
    when += " while blending into this description";
  } else if (span.blending > 0) {
    when += ", partly while blending into this description";
  }
  switch (kind) {
    case kTable:
      return "the camera is inside the table " + when + " (down to z = " + fixed(span.worst, 3) +
             " m): over the table and its rails keep it above the rails' top, z = " + fixed(layout.rail_top, 3) + " m";
    case kFloor:
      return "the camera is below the floor " + when + " (down to z = " + fixed(span.worst, 3) +
             " m): keep it above the floor, z = " + fixed(layout.floor, 3) + " m";
    case kLamp:
      return "the camera is inside the lamp over the table " + when + ": keep it out of the shade, x " +
             fixed(layout.lamp.x0, 2) + " to " + fixed(layout.lamp.x1, 2) + " m, y " + fixed(layout.lamp.y0, 2) +
             " to " + fixed(layout.lamp.y1, 2) + " m, z " + fixed(layout.lamp_bottom, 2) + " to " +
             fixed(layout.lamp_top, 2) + " m";
    default:
      return "the camera is too close to ball " + std::to_string(kind - kFirstBall) + " " + when + " (" +
             fixed(span.worst, 3) + " m from its centre): keep it at least " + fixed(checker.ball_clearance(), 3) +
             " m from a ball's centre, the ball's radius and " + fixed(kCameraBallClearance, 2) +
             " m of room for the lens";
  }
}

}  // namespace

void check_camera_clearance(const Scene& scene, const Timeline& timeline, const CameraScript& camera,
                            std::vector<Diagnostic>& diagnostics) {
  if (camera.segments().empty()) return;
  const Checker checker(scene, timeline, camera);
  const double duration = timeline.duration();

  // Every frame, every event, every blend's ends and the end of the shot.
  std::vector<double> times;
  for (int k = 0; k / static_cast<double>(kClearanceFps) < duration; ++k)
    times.push_back(k / static_cast<double>(kClearanceFps));
  for (const Event& event : timeline.events()) times.push_back(event.time);
  for (const CameraWindow& window : camera.windows()) {
    times.push_back(window.begin);
    times.push_back(window.end);
  }
  times.push_back(duration);
  std::erase_if(times, [duration](double t) { return t < 0 || t > duration; });
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());

  std::vector<Sample> samples;
  for (double t : times) samples.push_back(checker.sample(t));

  const double frame = 1.0 / kClearanceFps;
  const int kinds = kFirstBall + timeline.ball_count();
  std::vector<std::pair<double, Diagnostic>> found;  // by the span's start
  for (int kind = 0; kind < kinds; ++kind) {
    std::vector<Span> spans;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const std::optional<double> bad = checker.trouble(kind, samples[i]);
      if (!bad) continue;
      const int shot = samples[i].shot;
      const bool joins =
          !spans.empty() && spans.back().shot == shot &&
          (checker.state(kind, samples[i - 1]) == shot || samples[i].t - spans.back().end < frame + 1e-9);
      if (!joins) {
        const double begin = i == 0 ? samples[i].t : checker.edge(kind, shot, samples[i - 1].t, samples[i].t);
        spans.push_back({shot, begin, samples[i].t, *bad, 0, 0});
      }
      Span& span = spans.back();
      span.end = samples[i].t;
      span.worst = std::min(span.worst, *bad);
      ++span.samples;
      if (samples[i].blending) ++span.blending;
      const bool last = i + 1 == samples.size() || checker.state(kind, samples[i + 1]) != shot;
      if (last && i + 1 < samples.size()) span.end = checker.edge(kind, shot, samples[i + 1].t, samples[i].t);
    }
    for (const Span& span : spans) {
      const CameraShot& shot = camera.shots()[static_cast<std::size_t>(span.shot)];
      const SourceLoc loc = shot.loc.known() ? shot.loc : scene.camera_loc;
      found.push_back({span.begin, {Severity::warning, loc, message(kind, span, checker)}});
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& item : found) diagnostics.push_back(std::move(item.second));
}

}  // namespace bsim
