#pragma once
// The cue stick as a solid: a tapered rod from the tip (radius kCueTipRadius) to the butt
// (kCueButtRadius), kCueLength long. How close it comes to the bed, the cushions and the balls,
// and whether a camera can see it.
#include <vector>

#include "camera_script.h"
#include "cue_pose.h"
#include "scene.h"

namespace bsim {

/// m, the stick's radius at distance `s` from the tip along its axis.
double stick_radius(double s);

/// The smallest gap, m, between the stick and the bed, the cushions and the balls of `balls`
/// (pocketed ones ignored), skipping the ball `skip` (-1 for none); negative where it cuts in.
/// Each cushion is the block the table model puts behind its nose line: the cushion and the wood
/// together (kStandardTable.rail_reach() wide, beyond the line's ends round the table's corners, within
/// its frame), as high as the wood's top, less the pockets' openings (table_layout's PocketMouth: the
/// jaws' facings, the shelf and the hole), over which the stick may go lower.
double stick_clearance(const CuePose& stick, const Scene& scene, const std::vector<BallState>& balls,
                       double ball_radius, int skip = -1);

/// The gap, m, between the stick and one ball (negative where they overlap).
double stick_ball_gap(const CuePose& stick, const Vec3& centre, double ball_radius);

/// Whether any part of the stick can appear in the camera's picture.
bool stick_in_view(const CuePose& stick, const CameraPose& camera);

/// The share (0 to 1) of the camera's picture (kCameraFovDeg, kPictureAspect) the stick covers: its
/// outline (the tapered rod from tip to butt, the part nearer the camera than a few centimetres left
/// out) projected and clipped to the picture.
double stick_picture_share(const CuePose& stick, const CameraPose& camera);

/// Whether the stick stands in front of `p` (the centre of a ball of `radius` m, 0 for a point) as the
/// camera sees it: nearer than `p`, it passes within half the ball's radius of its centre in the
/// picture (so it covers a good part of the ball, not just an edge).
bool stick_hides(const CuePose& stick, const CameraPose& camera, const Vec3& p, double radius = 0);

}  // namespace bsim
