#include "look_regions.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene.h"
#include "table.h"

namespace bsim::test {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

/// Where the ray from `eye` along `d` enters the upright box [lo, hi], or kNever when it misses it.
double enters_box(const Vec3& eye, const Vec3& d, const Vec3& lo, const Vec3& hi) {
  double t0 = 0, t1 = kNever;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12) {
      if (eye[a] < lo[a] || eye[a] > hi[a]) return kNever;
      continue;
    }
    double near = (lo[a] - eye[a]) / d[a], far = (hi[a] - eye[a]) / d[a];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near), t1 = std::min(t1, far);
  }
  return t0 <= t1 ? t0 : kNever;
}

/// Where the ray reaches the plane where coordinate `a` is `v` (ahead only), or kNever.
double reaches(const Vec3& eye, const Vec3& d, int a, double v) {
  if (std::abs(d[a]) < 1e-12) return kNever;
  const double t = (v - eye[a]) / d[a];
  return t > 0 ? t : kNever;
}

bool inside(const TableRect& r, const Vec3& p) {
  return p.x() >= r.x0 && p.x() <= r.x1 && p.y() >= r.y0 && p.y() <= r.y1;
}

double luma(const std::vector<float>& rgb, std::size_t pixel) {
  return 0.2126 * rgb[3 * pixel] + 0.7152 * rgb[3 * pixel + 1] + 0.0722 * rgb[3 * pixel + 2];
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

/// The table description's boxes and the camera, found once for a picture.
class RegionCaster {
 public:
  RegionCaster(const Scene& scene, const CameraPose& pose, int width, int height)
      : layout_(table_layout(scene)),
        view_(pose, kCameraFovDeg, static_cast<double>(width) / height),
        width_(width),
        height_(height) {}

  LookRegion at(int x, int y) const {
    const Vec3 eye = view_.eye();
    const Vec3 d = view_.ray(picture_point(x + 0.5, y + 0.5, width_, height_));
    const TableRect& outer = layout_.wood_outer;
    const double table =
        enters_box(eye, d, Vec3(outer.x0, outer.y0, layout_.floor), Vec3(outer.x1, outer.y1, layout_.rail_top));
    const TableRect& shade = layout_.lamp;
    const double lamp = enters_box(eye, d, Vec3(shade.x0 - 0.01, shade.y0 - 0.01, layout_.lamp_bottom - 0.01),
                                   Vec3(shade.x1 + 0.01, shade.y1 + 0.01, kRoom.ceiling));
    // The bed: reached inside the noses, having come down past the cushions' top inside them too.
    const TableRect bed = layout_.noses.grown(-0.03);
    const double cloth = reaches(eye, d, 2, 0.0), over = reaches(eye, d, 2, layout_.rail_top);
    if (cloth < lamp && cloth < kNever && inside(bed, eye + cloth * d) &&
        (eye.z() <= layout_.rail_top || inside(bed, eye + over * d)))
      return inside(shade.grown(0.3), eye + cloth * d) ? LookRegion::cloth : LookRegion::other;
    if (table < kNever || lamp < kNever) return LookRegion::other;
    // Out of the room: the nearest of its faces ahead.
    const TableRect room = outer.grown(kRoom.margin);
    double leave = kNever;
    int face = -1;
    const double planes[6] = {room.x0, room.x1, room.y0, room.y1, layout_.floor, kRoom.ceiling};
    for (int f = 0; f < 6; ++f) {
      const double t = reaches(eye, d, f / 2, planes[f]);
      if (t < leave) leave = t, face = f;
    }
    if (face < 0) return LookRegion::other;
    const Vec3 p = eye + leave * d;
    if (face < 4)
      return p.z() > layout_.floor + 0.2 && p.z() < kRoom.ceiling - 0.1 ? LookRegion::wall : LookRegion::other;
    return face == 4 && inside(room.grown(-0.1), p) ? LookRegion::floor : LookRegion::other;
  }

 private:
  TableLayout layout_;
  CameraView view_;
  int width_, height_;
};

}  // namespace

LookRegion look_region(const Scene& scene, const CameraPose& pose, int width, int height, int x, int y) {
  return RegionCaster(scene, pose, width, height).at(x, y);
}

LookLuma look_luma(const Scene& scene, const CameraPose& pose, int width, int height, const std::vector<float>& rgb) {
  const RegionCaster cast(scene, pose, width, height);
  std::vector<double> cloth, wall, floor;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      switch (cast.at(x, y)) {
        case LookRegion::cloth: cloth.push_back(luma(rgb, pixel)); break;
        case LookRegion::wall: wall.push_back(luma(rgb, pixel)); break;
        case LookRegion::floor: floor.push_back(luma(rgb, pixel)); break;
        case LookRegion::other: break;
      }
    }
  }
  LookLuma l;
  l.cloth = median(cloth), l.wall = median(wall), l.floor = median(floor);
  l.cloth_pixels = static_cast<int>(cloth.size());
  l.wall_pixels = static_cast<int>(wall.size());
  l.floor_pixels = static_cast<int>(floor.size());
  return l;
}

}  // namespace bsim::test
