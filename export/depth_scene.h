#pragma once
// The depth picture the develop stage blurs each frame by (develop.h): how far from the camera, along
// its axis, the nearest surface lies behind each pixel, ray-cast in C++ from the core's own geometry,
// never traced by POV-Ray (a depth pass there costs 38 % more a frame at full size).
//
// What is cast: the balls as spheres where the frame shows them (a blurred ball at its place half-way
// through the open shutter, the frame's instant), the cue stick as a tapered rod, and the fixed scene
// as a handful of convex solids (the slate bed, each cushion's nose profile swept along its nose line
// and cut along its jaws' facings, the four wooden rails with their bevel, the table's body and legs,
// the lamp's shade as a box), less the pockets' openings (vertical columns through the bed and the
// wood), the pockets' cups seen from inside, and the room seen from inside. The models POV-Ray draws
// are finer (rounded jaw points, the lamp's open shade, the pictures on the walls, the legs' turning);
// where they differ by a centimetre or so the blur differs by a fraction of a pixel.
//
// The scene travels in the frames folder as text (frame_lens.h), so a render farm's node casts the
// same depth from the same numbers; the casting uses IEEE arithmetic only (+, -, *, /, sqrt), so it
// gives the same depth on every machine.
#include <optional>
#include <string>
#include <vector>

#include "camera_view.h"
#include "cue_pose.h"
#include "vec.h"

namespace bsim {

struct Scene;

/// A half-space: the points p with normal . p <= offset.
struct DepthPlane {
  Vec3 normal{0, 0, 1};
  double offset = 0;
};

/// A vertical column through everything, seen from above: a disc, or a convex polygon (its corners in
/// order). What a pocket's opening cuts out of the bed and the wood.
struct DepthColumn {
  bool disc = true;
  double cx = 0, cy = 0, radius = 0;
  std::vector<Vec3> corners;  ///< the polygon's corners (z ignored)
};

/// A convex solid (the intersection of its half-spaces) less some columns; `low` and `high` bound it.
struct DepthSolid {
  std::vector<DepthPlane> planes;
  std::vector<int> holes;  ///< indices into DepthScene::columns
  Vec3 low{0, 0, 0}, high{0, 0, 0};
};

/// An upright cylinder seen from inside (a pocket's cup): a ray that passes into it meets its far side.
struct DepthCup {
  double cx = 0, cy = 0, radius = 0, z0 = 0, z1 = 0;
};

/// What every frame of a movie shares: the fixed scene and the balls' size.
struct DepthScene {
  std::vector<DepthColumn> columns;
  std::vector<DepthSolid> solids;
  std::vector<DepthCup> cups;
  Vec3 room_low{0, 0, 0}, room_high{0, 0, 0};  ///< the room's box, seen from inside
  double ball_radius = 0;
};

/// What moves: the balls' centres and the stick (none when it is not in the scene).
struct DepthMoving {
  std::vector<Vec3> balls;
  std::optional<CuePose> stick;
};

/// The half-planes a x + b y <= c (z ignored) of a convex polygon's edges, whichever way round its
/// corners go.
std::vector<DepthPlane> polygon_planes(const std::vector<Vec3>& corners);

/// The fixed scene of `scene`'s table in its room, after the POV-Ray models (export/pov/table.inc,
/// room.inc) and the table description they read (table.h).
DepthScene depth_scene(const Scene& scene);

/// The scene as text lines (no trailing newline on the last), and read back: false, with `error`
/// saying what is wrong, for text that is not such a scene.
std::string depth_scene_text(const DepthScene& scene);
bool parse_depth_scene(const std::string& text, DepthScene& scene, std::string& error);

/// A depth picture: width x height distances (m) along the camera's axis, rows from the top.
struct DepthPicture {
  int width = 0;
  int height = 0;
  std::vector<float> depth;
};

/// Casts one ray through the centre of every pixel of a width x height picture from `view` (the
/// camera POV-Ray renders from) and keeps the nearest surface's distance along the view's axis.
DepthPicture cast_depth(const DepthScene& scene, const DepthMoving& moving, const CameraView& view, int width,
                        int height);

}  // namespace bsim
