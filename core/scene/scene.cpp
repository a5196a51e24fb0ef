#include "scene.h"

namespace bsim {

std::vector<Rail> standard_rails() {
  const TableSpec& t = kStandardTable;
  const double h = t.nose_height, x = t.half_length, y = t.half_width, c = t.corner_pocket_radius,
               s = t.side_pocket_radius;
  auto rail = [h](double ax, double ay, double bx, double by) { return Rail{Vec3(ax, ay, h), Vec3(bx, by, h), {}}; };
  return {rail(-x + c, y, -s, y), rail(s, y, x - c, y),     rail(x, y - c, x, -y + c),
          rail(x - c, -y, s, -y), rail(-s, -y, -x + c, -y), rail(-x, -y + c, -x, y - c)};
}

std::vector<Pocket> standard_pockets() {
  const TableSpec& t = kStandardTable;
  const double x = t.half_length, y = t.half_width, c = t.corner_pocket_radius, s = t.side_pocket_radius;
  auto pocket = [](double px, double py, double r) { return Pocket{Vec3(px, py, 0), r, {}}; };
  return {pocket(-x, y, c), pocket(0, y, s), pocket(x, y, c), pocket(x, -y, c), pocket(0, -y, s), pocket(-x, -y, c)};
}

}  // namespace bsim
