#pragma once
// Where a frame can differ from another frame of the same camera: found from the geometry the frames
// are written from (never by comparing pictures), so that only that part is traced again and every
// other pixel is taken from the other frame (see README "Tracing only what changed").
//
// A part (a ball or the stick) whose text in the two files differs has changed. What it changes in
// the picture lies, in each of the two frames, within:
// - the convex hull of its bound's spheres (pov_frame.h: a ball's streak, the stick's sweep or its
//   copies), as the camera projects it;
// - its shadow: the points of the scene the lamp's light reaches through it. Every sample of the
//   lamp's light lies in one horizontal rectangle above everything that moves; from a light point L
//   the shadow of a sphere S, down to the height z0, lies in the hull of S and S scaled from L by
//   (L.z - z0) / (L.z - top of S), and over the rectangle in the hull of those for its four corners
//   (the shadow point is affine in L). z0 is the cloth. Below the cloth the lamp reaches only into
//   the pockets' cups, through their openings, so a shadow reaching an opening adds all that the
//   lamp lights in that cup; beyond the table's frame below the cloth it lights nothing while the
//   room's walls are outside its cone (else such a shadow is followed down to the room's floor).
//   A piece wholly above the lamp's light casts nothing, and one far from the light seen from above
//   casts no further than the lamp's cone reaches (its cone is taken from the light's centre): so
//   the stick's butt swinging down through the light's plane beside the lamp is bounded too. The
//   other lights cast no shadow;
// - reflections: a ball's clear coat mirrors what is round it, but a sphere shows a point X only
//   where its normal bisects the directions to the eye and to X: each ball that stays as it was adds
//   the patch of its sphere where its normal lies between the way to the eye and the way to what
//   changed (mirror_patch), for each hull of what changed, and, when POV-Ray follows a reflection of
//   a reflection (max_trace_level), for every other ball (which may show the change) and for the
//   lamp shade when what changed reaches up to it. The lamp shade's lacquered outer faces are plane
//   mirrors, seen only from above its rim: what changed (and every ball) mirrored in each face the
//   camera sees, within the shade's picture. Nothing else in the models reflects.
// Each capsule of a bound is cut into pieces of at most kPieceLength, so that a long one (the stick
// lying across the picture) is held by a chain of small rectangles, not one box round it all. Each
// hull is projected and grown by kRegionMarginPixels, then snapped out to a grid of kRegionGrid pixels.
// POV-Ray traces any rectangle exactly as the whole frame: each pixel's antialiasing samples are
// traced at their own places, whatever block they fall in, and with the lamp's light in a light group
// (room.inc) no state passes from one pixel to the next. (An earlier measurement blamed the render
// blocks for a few differing pixels off their grid; the shadow cache was the cause.) The grid only
// keeps the rectangles few and their edges tidy.
#include <optional>
#include <vector>

#include "pov_frame.h"

namespace bsim {

struct Scene;

/// Pixels of the grid the rectangles are laid on.
inline constexpr int kRegionGrid = 8;
/// Pixels every projected bound is grown by before it is snapped to the grid: antialiasing samples a
/// pixel's corners, and the files' numbers are rounded.
inline constexpr int kRegionMarginPixels = 2;
/// Pixels a separate partial render is reckoned to cost for its start-up (POV-Ray's start, parse and
/// set-up: 0.05 s of CPU on a quiet machine, 0.1 to 0.2 s on a busy one, where the pixels of a final
/// frame's table cost 5 to 15 us each): two regions closer than that are rendered as one.
inline constexpr long kRegionStartPixels = 8192;
/// A frame whose region would cost more than this share of the whole picture (its pixels and its own
/// start) is rendered whole.
inline constexpr double kWholeShare = 0.85;
/// m, the longest piece of a bound's capsule projected on its own (the stick is cut into about 30).
inline constexpr double kPieceLength = 0.05;
/// The most pieces a capsule is cut into.
inline constexpr int kMostPieces = 64;
/// m out from the walls that what hangs on them (the cue rack, the pictures, the sconces) may reach.
inline constexpr double kWallDepth = 0.3;

/// Mirrors in a row a ray may meet when the include does not say (POV-Ray's default max_trace_level, 5,
/// less the ray from the eye).
inline constexpr int kMostReflections = 4;

/// Columns x0 to x1 - 1 and rows y0 to y1 - 1 of the picture (from its top-left corner).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  long area() const { return static_cast<long>(x1 - x0) * (y1 - y0); }
  bool operator==(const PixelRect&) const = default;
};

/// What of the fixed scene the bound needs (from the table description, as the include declares it).
struct RegionScene {
  double light_x0 = 0, light_y0 = 0, light_x1 = 0, light_y1 = 0;  ///< every light sample of the lamp lies in
  double light_z = 0;                                             ///< this rectangle at this height (m)
  double cone_deg = 90;  ///< the lamp lights nothing further than this from straight down from its centre
  Vec3 shade_min{0, 0, 0}, shade_max{0, 0, 0};  ///< the box round the lamp's lacquered shade
  /// A plane mirror: its outward unit normal and a point of it.
  struct Mirror {
    Vec3 normal{0, 0, 1}, point{0, 0, 0};
  };
  std::vector<Mirror> shade_faces;                                ///< the shade's lacquered outer faces
  double frame_x0 = 0, frame_y0 = 0, frame_x1 = 0, frame_y1 = 0;  ///< the table's wooden frame, seen from above
  double bed = 0;                                                 ///< just below the cloth's top
  double cup_floor = 0;                                           ///< below the lowest point of the pockets' cups
  double floor = 0;                                               ///< the room's floor
  /// Where the lamp's light can go down through a pocket below the cloth, seen from above: a disc that
  /// holds its hole (a cut pocket's shelf is cloth), or its whole opening for a pocket of another kind.
  struct Opening {
    double x = 0, y = 0, radius = 0;
  };
  std::vector<Opening> pockets;
  /// For each pocket, a hull round all that the lamp lights inside its cup.
  std::vector<std::vector<BoundSphere>> cups;
  /// Whether the lamp lights anything beyond the table's frame below the cloth (the walls within its
  /// cone): then a shadow that leaves the frame is followed down to the room's floor.
  bool lamp_lights_room = true;
  /// How many mirrors in a row a ray may meet (POV-Ray's max_trace_level, less the ray from the eye):
  /// from 2, a ball may show another ball's (or the shade's) image of a change.
  int reflections = kMostReflections;
};

RegionScene region_scene(const Scene& scene);

/// The rectangles (on the grid, sorted, none overlapping another) that hold every pixel in
/// which `frame` can differ from `reference`, a frame of the same camera, at width x height; none
/// when the two are the same. Nothing (render it whole) when the cameras differ, a bound reaches
/// behind the camera or above the lamp's light, or the rectangles would cost nearly the whole picture.
std::optional<std::vector<PixelRect>> changed_region(const FrameContent& reference, const FrameContent& frame,
                                                     const RegionScene& scene, int width, int height);

/// The part of mirroring ball `ball` (a ball's bound: its sphere grown by kBoundSlack) in which a ray
/// from `eye` can be reflected towards a point of `target`: by the law of reflection the normal there
/// is the bisector of the ways to the eye and to that point, each within a cone round the way from
/// the ball's centre (half-angles asin(r / distance to the eye), asin((r + target's radius) / its
/// distance)), so the normal lies within a cone round the bisector of the two axes; the sphere round
/// that cap of the ball. The whole ball when the cones allow any normal (`target` behind the ball,
/// nearly in line with the eye, or touching it).
BoundSphere mirror_patch(const BoundSphere& ball, const Vec3& eye, const BoundSphere& target);

/// Merges rectangles while one rectangle round two costs less than the two (a rectangle costing its
/// pixels and kRegionStartPixels), and drops any that another holds.
std::vector<PixelRect> merge_regions(std::vector<PixelRect> rects);

}  // namespace bsim
