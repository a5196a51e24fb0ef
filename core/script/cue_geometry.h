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

}  // namespace bsim
