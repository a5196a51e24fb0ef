#pragma once
// How bright the lit cloth, the walls and the floor come out in a rendered frame (linear light, as
// POV-Ray writes it in the .hdr), for the room's brightness against the cloth's (README "Light,
// motion blur and the look before and after"). Which pixels show which is found by casting each
// pixel's ray through the table description's boxes, not by the picture: a pixel counts as
//   - lit cloth when its ray reaches the bed inside the cushions' noses (3 cm in from them) and under
//     the lamp's shade grown by 0.3 m, having entered the cushions' box from above;
//   - wall when it leaves the room through a wall between 0.2 m above the floor and 0.1 m under the
//     ceiling without meeting the table's box or the lamp's;
//   - floor when it leaves the room through the floor more than 0.1 m from the walls without meeting
//     the table's box.
// Balls, the stick and what hangs on the walls are not cast: each region's median shrugs them off.
#include <vector>

#include "camera_view.h"

namespace bsim {
struct Scene;
}

namespace bsim::test {

/// Median Rec. 709 luma (of linear light) of each region and how many pixels it had.
struct LookLuma {
  double cloth = 0, wall = 0, floor = 0;
  int cloth_pixels = 0, wall_pixels = 0, floor_pixels = 0;
};

/// What a pixel of the picture shows, as the ray-cast above decides.
enum class LookRegion { other, cloth, wall, floor };

/// The region pixel (x, y) (from the top-left corner) of a width x height picture from `pose` shows.
LookRegion look_region(const Scene& scene, const CameraPose& pose, int width, int height, int x, int y);

/// The medians over a width x height linear-light RGB picture (three floats a pixel, rows from the
/// top) seen from `pose`.
LookLuma look_luma(const Scene& scene, const CameraPose& pose, int width, int height, const std::vector<float>& rgb);

}  // namespace bsim::test
