#include "table.h"

#include <algorithm>

#include "scene.h"

namespace bsim {

TableLayout table_layout(const Scene& scene) {
  const TableSpec& spec = kStandardTable;
  TableLayout layout;
  layout.noses = {-spec.half_length, -spec.half_width, spec.half_length, spec.half_width};
  layout.nose_height = spec.nose_height;
  if (!scene.rails.empty()) {
    const Vec3& first = scene.rails.front().a;
    layout.noses = {first.x(), first.y(), first.x(), first.y()};
    layout.nose_height = 0;
    for (const Rail& rail : scene.rails) {
      for (const Vec3& p : {rail.a, rail.b}) {
        layout.noses = {std::min(layout.noses.x0, p.x()), std::min(layout.noses.y0, p.y()),
                        std::max(layout.noses.x1, p.x()), std::max(layout.noses.y1, p.y())};
        layout.nose_height = std::max(layout.nose_height, p.z());
      }
    }
  }
  layout.wood_inner = layout.noses.grown(spec.cushion.width);
  layout.wood_outer = layout.wood_inner.grown(spec.rail.width);
  layout.cushion_top = layout.nose_height + spec.cushion.top_rise;
  layout.rail_top = layout.nose_height + spec.rail.top_rise;
  layout.floor = -spec.bed_height;

  const LampSpec& lamp = kRoom.lamp;
  const double middle_x = 0.5 * (layout.noses.x0 + layout.noses.x1);
  const double middle_y = 0.5 * (layout.noses.y0 + layout.noses.y1);
  const double half_length = std::max(lamp.min_half_length, lamp.length_share * (layout.noses.x1 - layout.noses.x0));
  layout.lamp = {middle_x - half_length, middle_y - lamp.half_width, middle_x + half_length,
                 middle_y + lamp.half_width};
  layout.lamp_bottom = lamp.bottom;
  layout.lamp_top = lamp.bottom + lamp.height;

  const TableRect& n = layout.noses;
  const double d = spec.sights.from_nose, z = layout.rail_top;
  for (int i = 1; i < spec.sights.long_spaces; ++i) {
    if (2 * i == spec.sights.long_spaces) continue;  // the side pocket
    const double x = n.x0 + (n.x1 - n.x0) * i / spec.sights.long_spaces;
    layout.sights.push_back({Vec3(x, n.y0 - d, z), true});
    layout.sights.push_back({Vec3(x, n.y1 + d, z), true});
  }
  for (int i = 1; i < spec.sights.short_spaces; ++i) {
    const double y = n.y0 + (n.y1 - n.y0) * i / spec.sights.short_spaces;
    layout.sights.push_back({Vec3(n.x0 - d, y, z), false});
    layout.sights.push_back({Vec3(n.x1 + d, y, z), false});
  }
  return layout;
}

}  // namespace bsim
