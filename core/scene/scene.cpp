#include "scene.h"

namespace bsim {

namespace {
constexpr double kHalfLength = 1.27;   // m, cushion nose to nose along x / 2
constexpr double kHalfWidth = 0.635;   // m, along y / 2
constexpr double kCornerRadius = 0.08; // m
constexpr double kSideRadius = 0.065;  // m
}  // namespace

std::vector<Rail> standard_rails() {
  const double h = kStandardNoseHeight, x = kHalfLength, y = kHalfWidth, c = kCornerRadius, s = kSideRadius;
  auto rail = [h](double ax, double ay, double bx, double by) { return Rail{Vec3(ax, ay, h), Vec3(bx, by, h), {}}; };
  return {rail(-x + c, y, -s, y), rail(s, y, x - c, y),  rail(x, y - c, x, -y + c),
          rail(x - c, -y, s, -y), rail(-s, -y, -x + c, -y), rail(-x, -y + c, -x, y - c)};
}

std::vector<Pocket> standard_pockets() {
  const double x = kHalfLength, y = kHalfWidth;
  auto pocket = [](double px, double py, double r) { return Pocket{Vec3(px, py, 0), r, {}}; };
  return {pocket(-x, y, kCornerRadius), pocket(0, y, kSideRadius),  pocket(x, y, kCornerRadius),
          pocket(x, -y, kCornerRadius), pocket(0, -y, kSideRadius), pocket(-x, -y, kCornerRadius)};
}

}  // namespace bsim
