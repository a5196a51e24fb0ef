#pragma once
// Where a ball could leave the table: the gaps in a table's cushions that no pocket fills.
//
// The cushions' nose lines are joined end to end into closed outlines: each rail's second end is
// paired with the nearest free first end of a rail (the shortest pairs first), so a table's rails go
// round it clockwise with a gap at every pocket, and a free-standing cushion inside the table closes
// on itself. An outline walked clockwise (its playing side inside) bounds the bed; one walked the
// other way, or round no area, is an obstacle on it.
//
// A ball's centre stays at least its reach (detect.h's cushion_reach) from every nose line and end, so
// it can only leave a clockwise outline through a gap between two rail ends further apart than the two
// reaches, and only through the part of the gap at least a reach from each end: its passage. A gap is
// open when some point of its passage lies outside every pocket's drop circle: a ball crossing there
// rolls off the table instead of dropping. A cushion whose nose stands at or above the ball's diameter
// (or at or below the bed) does not stop a ball at all; on a clockwise outline it is a gap of its own.
#include <vector>

#include "scene.h"

namespace bsim {

/// m, how close a ball's centre comes to a nose line at `nose_height` above the bed (0: it passes):
/// sqrt(R^2 - (h - R)^2), the physics' cushion contact distance too (detect.h's cushion_reach).
double nose_reach(double ball_radius, double nose_height);

struct CushionGap {
  int from_rail = -1;  ///< the rail whose second end opens the gap
  int to_rail = -1;    ///< the rail whose first end closes it (the same rail: it closes on itself)
  Vec3 a{0, 0, 0};     ///< plan points: the second end of from_rail
  Vec3 b{0, 0, 0};     ///< and the first end of to_rail
  bool under = false;  ///< the rail from_rail itself lets balls under it (a and b are its ends)
};

/// The open gaps of the outlines that bound the bed, in rail order; `enclosed` is set when some
/// clockwise outline bounds the bed at all (no rails: the table is open everywhere).
std::vector<CushionGap> open_cushion_gaps(const std::vector<Rail>& rails, const std::vector<Pocket>& pockets,
                                          double ball_radius, bool& enclosed);

}  // namespace bsim
