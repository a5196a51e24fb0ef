// Casting the depth picture (depth_scene.h): every pixel's ray against the things that may lie behind
// it. Each thing is bounded by boxes (a long one cut into pieces), each box's place in the picture
// marks the tiles of 16 x 16 pixels it may cover, and a pixel's ray meets only the things of its tile.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "depth_scene.h"

namespace bsim {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Pixels, a tile's side.
constexpr int kTile = 16;
/// m, the longest side of a piece of a thing's bounding box projected on its own, so a long cushion
/// marks a chain of tiles, not every tile of the box round it.
constexpr double kPiece = 0.25;

/// The ray's interval [t0, t1] inside a convex thing (empty when t0 > t1).
struct Interval {
  double t0 = -kInfinity, t1 = kInfinity;
  bool empty() const { return t0 > t1; }
  /// Clips to the half-space n . p <= c along eye + t d, given den = n . d and num = c - n . eye.
  void clip(double den, double num) {
    if (den > 0)
      t1 = std::min(t1, num / den);
    else if (den < 0)
      t0 = std::max(t0, num / den);
    else if (num < 0)
      t0 = kInfinity;
  }
};

/// A column prepared for one eye: a disc's centre, or a polygon's edges (a x + b y <= c).
struct ColumnCast {
  bool disc = true;
  double cx = 0, cy = 0, r2 = 0;
  double ox = 0, oy = 0;                     ///< the eye less the centre
  std::vector<std::array<double, 3>> edges;  ///< a, b, c
  std::vector<double> edge_num;              ///< c - (a, b) . eye

  ColumnCast(const DepthColumn& c, const Vec3& eye) : disc(c.disc) {
    if (disc) {
      cx = c.cx, cy = c.cy, r2 = c.radius * c.radius;
      ox = eye.x() - cx, oy = eye.y() - cy;
      return;
    }
    for (const DepthPlane& p : polygon_planes(c.corners)) {
      edges.push_back({p.normal.x(), p.normal.y(), p.offset});
      edge_num.push_back(p.offset - p.normal.x() * eye.x() - p.normal.y() * eye.y());
    }
  }

  /// Whether the plan point (x, y) lies inside.
  bool contains(double x, double y) const {
    if (disc) return (x - cx) * (x - cx) + (y - cy) * (y - cy) < r2;
    for (const auto& e : edges)
      if (e[0] * x + e[1] * y > e[2]) return false;
    return true;
  }

  /// Where the ray (from the eye along d) leaves the column.
  double exit(const Vec3& d) const {
    if (!disc) {
      Interval in;
      for (std::size_t i = 0; i < edges.size(); ++i) in.clip(edges[i][0] * d.x() + edges[i][1] * d.y(), edge_num[i]);
      return in.t1;
    }
    const double a = d.x() * d.x() + d.y() * d.y(), b = ox * d.x() + oy * d.y(), c = ox * ox + oy * oy - r2;
    if (a < 1e-18) return kInfinity;
    const double disc2 = b * b - a * c;
    return disc2 < 0 ? -kInfinity : (-b + std::sqrt(disc2)) / a;
  }
};

/// A thing the rays may meet: where a ray from the eye along unit d first meets it (kInfinity: nowhere, or
/// not nearer than `nearest`).
class Caster {
 public:
  virtual ~Caster() = default;
  virtual double hit(const Vec3& d, double nearest) const = 0;
  /// Boxes holding all of the thing (none: it may be anywhere in the picture).
  std::vector<std::pair<Vec3, Vec3>> boxes;
};

/// Calls visit(low, high) for each piece of the box [low, high], at most kPiece along each side.
template <class Visit>
void box_pieces(const Vec3& low, const Vec3& high, Visit&& visit) {
  std::array<int, 3> n{};
  for (int i = 0; i < 3; ++i) n[i] = std::clamp(static_cast<int>(std::ceil((high[i] - low[i]) / kPiece)), 1, 32);
  const Vec3 step = (high - low).cwiseQuotient(Vec3(n[0], n[1], n[2]));
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const Vec3 a = low + step.cwiseProduct(Vec3(i, j, k));
        visit(a, (i + 1 == n[0] && j + 1 == n[1] && k + 1 == n[2]) ? high : Vec3(a + step));
      }
}

/// The room's box from inside: where the ray leaves it.
class RoomCaster : public Caster {
 public:
  RoomCaster(const DepthScene& scene, const Vec3& eye) : low_(scene.room_low - eye), high_(scene.room_high - eye) {}
  double hit(const Vec3& d, double) const override {
    double t = kInfinity;
    for (int i = 0; i < 3; ++i) {
      if (d[i] > 0) t = std::min(t, high_[i] / d[i]);
      if (d[i] < 0) t = std::min(t, low_[i] / d[i]);
    }
    return t > 0 ? t : kInfinity;
  }

 private:
  Vec3 low_, high_;
};

/// A convex solid less its columns.
class SolidCaster : public Caster {
 public:
  SolidCaster(const DepthSolid& s, const Vec3& eye, const std::vector<ColumnCast>& columns)
      : eye_(eye), columns_(columns), holes_(s.holes) {
    for (const DepthPlane& p : s.planes) planes_.emplace_back(p.normal, p.offset - p.normal.dot(eye));
    box_pieces(s.low, s.high, [&](const Vec3& a, const Vec3& b) { boxes.emplace_back(a, b); });
  }
  double hit(const Vec3& d, double nearest) const override {
    Interval in;
    for (const auto& [n, num] : planes_) {
      in.clip(n.dot(d), num);
      if (in.empty() || in.t0 >= nearest) return kInfinity;  // missed, or behind a nearer thing
    }
    if (in.t0 <= 0) return kInfinity;  // the eye inside it, or it behind the eye
    double t = in.t0;
    for (bool moved = !holes_.empty(); moved && t <= in.t1;) {
      moved = false;
      const double x = eye_.x() + t * d.x(), y = eye_.y() + t * d.y();
      for (int h : holes_) {
        const ColumnCast& c = columns_[static_cast<std::size_t>(h)];
        if (!c.contains(x, y)) continue;
        const double out = c.exit(d);
        if (out > t) {
          t = out;
          moved = true;
          break;
        }
      }
    }
    return t <= in.t1 ? t : kInfinity;
  }

 private:
  Vec3 eye_;
  const std::vector<ColumnCast>& columns_;
  std::vector<int> holes_;
  std::vector<std::pair<Vec3, double>> planes_;
};

/// A pocket's cup from inside: where the ray leaves the upright cylinder it passed into.
class CupCaster : public Caster {
 public:
  CupCaster(const DepthCup& c, const Vec3& eye) : c_(c), eye_(eye) {
    boxes.emplace_back(Vec3(c.cx - c.radius, c.cy - c.radius, c.z0), Vec3(c.cx + c.radius, c.cy + c.radius, c.z1));
  }
  double hit(const Vec3& d, double nearest) const override {
    const double ox = eye_.x() - c_.cx, oy = eye_.y() - c_.cy;
    const double a = d.x() * d.x() + d.y() * d.y(), b = ox * d.x() + oy * d.y(),
                 c = ox * ox + oy * oy - c_.radius * c_.radius;
    const double disc = b * b - a * c;
    Interval in;  // an upright ray stays in the column, or out of it, all the way
    if (a < 1e-18 ? c > 0 : disc < 0) return kInfinity;
    if (a >= 1e-18) {
      const double root = std::sqrt(disc);
      in = {(-b - root) / a, (-b + root) / a};
    }
    in.clip(d.z(), c_.z1 - eye_.z());
    in.clip(-d.z(), eye_.z() - c_.z0);
    return !in.empty() && in.t1 > std::max(in.t0, 0.0) && in.t1 < nearest ? in.t1 : kInfinity;
  }

 private:
  DepthCup c_;
  Vec3 eye_;
};

class BallCaster : public Caster {
 public:
  BallCaster(const Vec3& centre, double radius, const Vec3& eye) : oc_(eye - centre), r2_(radius * radius) {
    boxes.emplace_back(centre - Vec3::Constant(radius), centre + Vec3::Constant(radius));
  }
  double hit(const Vec3& d, double) const override {
    const double b = oc_.dot(d), disc = b * b - (oc_.dot(oc_) - r2_);
    if (disc < 0) return kInfinity;
    const double t = -b - std::sqrt(disc);
    return t > 0 ? t : kInfinity;
  }

 private:
  Vec3 oc_;
  double r2_;
};

/// The stick: a cone frustum from its tip (radius kCueTipRadius) to its butt, with flat ends.
class StickCaster : public Caster {
 public:
  StickCaster(const CuePose& cue, const Vec3& eye) : w_(eye - cue.tip), axis_(cue.axis.normalized()) {
    constexpr int kPieces = 16;
    for (int k = 0; k < kPieces; ++k) {
      const Vec3 a = cue.tip + (kCueLength * k / kPieces) * axis_,
                 b = cue.tip + (kCueLength * (k + 1) / kPieces) * axis_;
      boxes.emplace_back(a.cwiseMin(b) - Vec3::Constant(kCueButtRadius),
                         a.cwiseMax(b) + Vec3::Constant(kCueButtRadius));
    }
  }
  double hit(const Vec3& d, double) const override {
    const double da = d.dot(axis_), wa = w_.dot(axis_), r0 = kCueTipRadius, length = kCueLength;
    const double slope = (kCueButtRadius - kCueTipRadius) / kCueLength;
    double best = kInfinity;
    // The side: |w + t d|^2 - s^2 = (r0 + slope s)^2, s = wa + t da the place along the axis.
    const double k = 1 + slope * slope;
    const double a = 1 - k * da * da, b = w_.dot(d) - k * wa * da - r0 * slope * da;
    const double c = w_.dot(w_) - k * wa * wa - 2 * r0 * slope * wa - r0 * r0;
    const double disc = b * b - a * c;
    if (std::abs(a) > 1e-12 && disc >= 0) {
      const double root = std::sqrt(disc);
      for (double t : {(-b - root) / a, (-b + root) / a}) {
        const double s = wa + t * da;
        if (t > 0 && s >= 0 && s <= length && t < best) best = t;
      }
    }
    // The two ends.
    if (std::abs(da) > 1e-12)
      for (const auto& [s, r] : {std::pair{0.0, r0}, std::pair{length, r0 + slope * length}}) {
        const double t = (s - wa) / da;
        if (t > 0 && t < best && (w_ + t * d - s * axis_).squaredNorm() <= r * r) best = t;
      }
    return best;
  }

 private:
  Vec3 w_, axis_;  ///< the eye less the tip; unit, tip to butt
};

/// Columns x0 to x1 - 1 and rows y0 to y1 - 1 of the picture.
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// The pixels a box can cover in the picture, a pixel wider all round: all of it when part of the box
/// is not in front of the eye.
Rect box_rect(const Vec3& low, const Vec3& high, const CameraView& view, int width, int height) {
  double x0 = kInfinity, y0 = kInfinity, x1 = -kInfinity, y1 = -kInfinity;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? high.x() : low.x(), corner & 2 ? high.y() : low.y(), corner & 4 ? high.z() : low.z());
    const std::optional<PicturePoint> at = view.depth(p) > 1e-3 ? view.project(p) : std::nullopt;
    if (!at) return {0, 0, width, height};
    const double px = 0.5 * width * (1 + at->x), py = 0.5 * height * (1 - at->y);
    x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
  }
  const auto clamp = [](double v, int hi) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi))); };
  return {clamp(std::floor(x0) - 1, width), clamp(std::floor(y0) - 1, height), clamp(std::ceil(x1) + 1, width),
          clamp(std::ceil(y1) + 1, height)};
}

/// m from the eye to the nearest point of a box.
double box_distance(const Vec3& eye, const Vec3& low, const Vec3& high) {
  return (eye.cwiseMax(low).cwiseMin(high) - eye).norm();
}

/// Every thing of the frame, the nearest first (by its bounding box), so a ray meets a near thing
/// before the solids behind it, which it then leaves as soon as they lie farther; the room last.
std::vector<std::unique_ptr<Caster>> casters(const DepthScene& scene, const DepthMoving& moving, const Vec3& eye,
                                             const std::vector<ColumnCast>& columns) {
  std::vector<std::pair<double, std::unique_ptr<Caster>>> near;
  const auto add = [&](std::unique_ptr<Caster> caster) {
    double distance = kInfinity;
    for (const auto& [low, high] : caster->boxes) distance = std::min(distance, box_distance(eye, low, high));
    near.emplace_back(distance, std::move(caster));
  };
  for (const Vec3& centre : moving.balls) add(std::make_unique<BallCaster>(centre, scene.ball_radius, eye));
  if (moving.stick) add(std::make_unique<StickCaster>(*moving.stick, eye));
  for (const DepthSolid& s : scene.solids) add(std::make_unique<SolidCaster>(s, eye, columns));
  for (const DepthCup& c : scene.cups) add(std::make_unique<CupCaster>(c, eye));
  std::stable_sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::unique_ptr<Caster>> all;
  for (auto& entry : near) all.push_back(std::move(entry.second));
  all.push_back(std::make_unique<RoomCaster>(scene, eye));
  return all;
}

}  // namespace

DepthPicture cast_depth(const DepthScene& scene, const DepthMoving& moving, const CameraView& view, int width,
                        int height) {
  DepthPicture out{width, height, std::vector<float>(static_cast<std::size_t>(width) * height)};
  if (width <= 0 || height <= 0) return out;
  std::vector<ColumnCast> columns;
  for (const DepthColumn& c : scene.columns) columns.emplace_back(c, view.eye());
  const std::vector<std::unique_ptr<Caster>> all = casters(scene, moving, view.eye(), columns);
  // Each tile's things, in the order above, each once.
  const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
  std::vector<std::vector<const Caster*>> tiles(static_cast<std::size_t>(tiles_x) * tiles_y);
  for (const std::unique_ptr<Caster>& caster : all) {
    const auto mark = [&](const Rect& r) {
      for (int ty = r.y0 / kTile; ty * kTile < r.y1; ++ty)
        for (int tx = r.x0 / kTile; tx * kTile < r.x1; ++tx) {
          auto& list = tiles[static_cast<std::size_t>(ty) * tiles_x + tx];
          if (list.empty() || list.back() != caster.get()) list.push_back(caster.get());
        }
    };
    if (caster->boxes.empty()) mark({0, 0, width, height});
    for (const auto& [low, high] : caster->boxes) mark(box_rect(low, high, view, width, height));
  }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec3 d = view.ray(picture_point(x + 0.5, y + 0.5, width, height));
      double nearest = kInfinity;
      for (const Caster* c : tiles[static_cast<std::size_t>(y / kTile) * tiles_x + x / kTile])
        nearest = std::min(nearest, c->hit(d, nearest));
      out.depth[static_cast<std::size_t>(y) * width + x] = static_cast<float>(nearest * d.dot(view.forward()));
    }
  return out;
}

}  // namespace bsim
