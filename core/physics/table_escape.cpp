#include "table_escape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "motion.h"
#include "roots.h"

namespace bsim {

namespace {

/// The first t in [0, length] where c0 + c1 t + c2 t^2 > 0, if any (the roots by roots.h).
std::optional<double> first_positive(double c0, double c1, double c2, double length) {
  if (c0 > 0) return 0.0;
  const Roots roots = roots_in(Poly{{c0, c1, c2, 0, 0}}, 0.0, length);
  for (int k = 0; k < roots.count; ++k)
    if (c1 + 2 * c2 * roots.t[static_cast<std::size_t>(k)] > 0) return roots.t[static_cast<std::size_t>(k)];
  if (c0 + length * (c1 + length * c2) > 0) return length;
  return std::nullopt;
}

struct Box {
  double lo[2] = {0, 0}, hi[2] = {0, 0};
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v == 0.0 ? 0.0 : v);
  return text;
}

std::optional<Box> cushion_box(const Scene& scene) {
  if (scene.rails.empty()) return std::nullopt;
  Box box;
  box.lo[0] = box.lo[1] = std::numeric_limits<double>::infinity();
  box.hi[0] = box.hi[1] = -box.lo[0];
  for (const Rail& rail : scene.rails)
    for (const Vec3* p : {&rail.a, &rail.b})
      for (int k = 0; k < 2; ++k) {
        box.lo[k] = std::min(box.lo[k], (*p)[k]);
        box.hi[k] = std::max(box.hi[k], (*p)[k]);
      }
  if (!(box.lo[0] < box.hi[0] && box.lo[1] < box.hi[1])) return std::nullopt;
  return box;
}

/// Whether plan point p lies in one of the cut pockets' openings (between the facings or over the hole).
bool on_a_shelf(const std::vector<PocketMouth>& mouths, const Vec3& p) {
  return std::any_of(mouths.begin(), mouths.end(),
                     [&](const PocketMouth& m) { return m.in_throat(p, kEscapeTolerance); });
}

}  // namespace

std::optional<TableEscape> first_escape(const Scene& scene, const SimulationResult& result) {
  const std::optional<Box> box = cushion_box(scene);
  if (!box) return std::nullopt;
  const PhysicsParams& params = scene.physics;
  std::vector<PocketMouth> mouths;
  for (const Pocket& pocket : scene.pockets)
    if (const PocketMouth m = pocket_mouth(pocket, scene.rails); m.cut) mouths.push_back(m);
  std::optional<TableEscape> first;
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const auto& list = result.segments[i];
    for (std::size_t k = 0; k < list.size(); ++k) {
      const MotionSegment& seg = list[k];
      if (!on_bed(seg.start) || (first && seg.t0 >= first->time)) continue;
      double end = k + 1 < list.size() ? list[k + 1].t0 : std::max(seg.t0, result.rest);
      end = std::min(end, seg.t0 + transition_time(seg.start, params));
      const Path path = path_of(seg.start, params);
      for (int axis = 0; axis < 2; ++axis)
        for (double side : {1.0, -1.0}) {
          // side * (p + v t + a t^2 / 2) beyond side * the box's edge, plus the tolerance.
          const double edge = side > 0 ? box->hi[axis] : box->lo[axis];
          const std::optional<double> t =
              first_positive(side * (path.p[axis] - edge) - kEscapeTolerance, side * path.v[axis],
                             side * 0.5 * path.a[axis], std::max(0.0, end - seg.t0));
          // A ball on a cut pocket's shelf (between its facings, short of the hole) is on the table.
          if (t && on_a_shelf(mouths, path.at(*t))) continue;
          if (t && (!first || seg.t0 + *t < first->time))
            first = TableEscape{static_cast<int>(i), seg.t0 + *t, path.at(*t)};
        }
    }
  }
  return first;
}

std::string escape_message(const Scene& scene, const TableEscape& escape, double offset) {
  const std::optional<Box> box = cushion_box(scene);
  const int painted = scene.ball(escape.ball).number;
  const std::string name = (painted == 0 ? "the cue ball" : "the " + std::to_string(painted)) + " (ball index " +
                           std::to_string(escape.ball) + ")";
  std::string message = name + " left the table at " + number(escape.time + offset) + " s, at " +
                        plan_text(escape.where) + ", without dropping into a pocket";
  if (box)
    message += ": its centre is beyond the cushions (x from " + number(box->lo[0]) + " to " + number(box->hi[0]) +
               ", y from " + number(box->lo[1]) + " to " + number(box->hi[1]) + ")";
  return message +
         "; nothing was written. The scene check lets no ball off a table whose cushions close round it, "
         "so this is a fault of the program: please report it with the scene";
}

}  // namespace bsim
