#include "director_candidates.h"

#include <algorithm>
#include <cmath>

#include "camera_moment.h"
#include "camera_view.h"

namespace bsim::directing {

namespace {

double hundredths(double v) { return std::round(v * 100.0) / 100.0; }

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

}  // namespace

std::vector<CameraShot> stroke_places(const FilmedStroke& stroke, double radius, const TableLayout& layout) {
  const Vec3& c0 = stroke.cue_at;
  const Vec3& aim = stroke.aim;
  const double reach =
      stroke.first_object >= 0 ? std::clamp(0.45 * (stroke.first_object_at - c0).norm(), 0.2, 0.7) : 0.4;
  const Vec3 stroke_target = to_millimetre(Vec3(c0.x() + reach * aim.x(), c0.y() + reach * aim.y(), radius));
  std::vector<CameraShot> places;
  // On the line of aim first; then a step to either side of it, over the shooter's shoulder, for a
  // stick raised over a cushion that a camera on the line would look along (kDirectorStickShare).
  const Vec3 right(aim.y(), -aim.x(), 0);
  for (double side : {0.0, 0.3, -0.3})
    for (double back : {0.8, 1.0, 1.25, 1.6, 2.0})
      for (double up : {0.45, 0.6, 0.8, 1.0}) {
        CameraShot s;
        s.mode = CameraMode::hover;
        s.location = to_millimetre(c0 - back * aim + side * right + Vec3(0, 0, up));
        s.target = stroke_target;
        if (clear_of_room(layout, s.location)) places.push_back(s);
      }
  return places;
}

std::vector<CameraShot> ball_places(int subject, const Vec3& middle, double peak_speed, const Vec3& previous,
                                    const LineOfAction& line, const Vec3& aim, const TableLayout& layout) {
  const double wanted = side_to_keep(line, previous);
  std::vector<Costed> options;
  const auto add_look = [&](const Vec3& location, double cost) {
    const Vec3 p = to_millimetre(location);
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
        f.location = to_millimetre(offset);
        options.push_back({0.9 + 0.1 * offset.norm(), f});
      }
  }
  return cheapest_first(std::move(options));
}

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

std::vector<CameraShot> wide_places(const TableLayout& layout, const Vec3& previous, const LineOfAction& line) {
  const TableRect n = layout.noses;
  const Vec3 centre(to_millimetre(0.5 * (n.x0 + n.x1)), to_millimetre(0.5 * (n.y0 + n.y1)), 0);
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
        s.location = to_millimetre(centre + distance * direction);
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

Timings wide_timings(double since) {
  Timings timings;
  for (double post : {0.35, 0.5, 0.65, 0.8, 0.95}) timings.usual.push_back({0.0, post});
  for (double lead : {0.4, 0.8})
    for (double post : {0.35, 0.65, 0.95}) timings.early.push_back({hundredths(std::min(0.5, lead / since)), post});
  return timings;
}

}  // namespace bsim::directing
