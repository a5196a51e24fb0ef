#pragma once
// The pool table, one description for every reader: the physics' standard table (its bed, noses
// and pockets), the cue stick's clearance over the cushions, and both front ends' models (the GL
// preview's meshes and the POV-Ray include). A scene may bring its own nose lines and pockets; the
// cushion profile, the wooden rail, the sights and the bed's height above the floor are the same
// on every table.
//
// Numbers are a standard 9-foot pool table's, after the WPA equipment specifications where they
// give one (marked "WPA"); the rest (which the WPA leaves open) are typical of commercial tables
// with K-66 cushions.
#include <numbers>
#include <vector>

#include "vec.h"

namespace bsim {

struct Scene;
struct Rail;
struct Pocket;

/// The cushion's cross-section, measured from its nose line outward.
struct CushionProfile {
  double width = 0;     ///< m, the cloth-covered cushion's top from the nose to the wood
  double top_rise = 0;  ///< m, the cushion's top above its nose
  double undercut = 0;  ///< m, how far behind the nose the cushion's foot meets the bed
};

/// The wooden rail (the rail cap) that holds the cushion, seen from above.
struct WoodRail {
  double width = 0;     ///< m, the wood's top from the cushion to the table's outer edge
  double top_rise = 0;  ///< m, the wood's top above the cushion nose
};

/// The pockets' jaws, shelves, holes and cups, after the WPA and BCA equipment specifications: each
/// cushion ends at a jaw point, where its nose changes direction into the pocket, and is cut, with its
/// wood backing, along a facing at a fixed horizontal angle to the nose. Behind the mouth (the line
/// between the two jaw points) the bed goes on as a shelf to the slate's edge, where a round hole drops
/// into the cup. The mouths, the shelves and the jaw points' rounding are `param`s (PhysicsParams).
struct PocketJaws {
  double corner_facing_deg = 0;  ///< deg between a corner pocket's cushion nose and its facing
  double side_facing_deg = 0;    ///< and a side pocket's
  double corner_hole = 0;        ///< m, the radius of the hole cut in the slate behind a corner's shelf
  double side_hole = 0;          ///< and behind a side pocket's
  /// m, the drop circles of the standard pockets on a table whose cushions are the scene's own (`rail`
  /// lines): round holes centred on the noses' corners and middles, with no jaws of their own.
  double bare_corner_radius = 0;
  double bare_side_radius = 0;
  double side_within_deg = 0;  ///< two jaws' noses this close to one line make a side pocket
  double near_end = 0;         ///< m beyond a bare pocket's drop circle a nose end still counts as a jaw
  double liner = 0;            ///< m, the leather liner lining the throat through the wood and the cup
  double lip_round = 0;        ///< m, the radius of the slate's edge the cloth wraps over into the hole
};

/// The diamond sights inlaid in the wood's top.
struct Sights {
  int long_spaces = 0;   ///< the long side between its corner pockets is divided into this many spaces
  int short_spaces = 0;  ///< and the short side into this many; a sight marks each division
  double from_nose = 0;  ///< m, each sight's centre from the cushion's nose line
  double length = 0;     ///< m, the diamond's diagonal along the rail
  double width = 0;      ///< m, its diagonal across the rail
};

struct TableSpec {
  double half_length = 0;  ///< m, half the bed from nose to nose along x
  double half_width = 0;   ///< m, half the bed from nose to nose along y
  double nose_height = 0;  ///< m, the cushion nose above the bed
  double bed_height = 0;   ///< m, the bed above the floor
  CushionProfile cushion;
  WoodRail rail;
  Sights sights;
  PocketJaws jaws;

  /// m from the nose line to the table's outer edge: cushion and wood together, all that a cue
  /// stick reaching over a cushion must clear.
  constexpr double rail_reach() const { return cushion.width + rail.width; }
};

/// The standard 9-foot pool table.
inline constexpr TableSpec kStandardTable{
    // WPA: the playing surface is 100 x 50 in (2.54 x 1.27 m) between the cushion noses.
    .half_length = 1.27,
    .half_width = 0.635,
    // WPA: the nose stands 62.5 % to 64.5 % of the ball's diameter above the bed; 63.5 % of
    // 57.15 mm is 36.3 mm (1 7/16 in).
    .nose_height = 0.0363,
    // WPA: the bed stands 29 1/4 to 31 in (0.743 to 0.787 m) above the floor.
    .bed_height = 0.76,
    .cushion =
        {
            // WPA: the cloth-covered cushion is 1 7/8 to 2 in wide from the feather strip's outer
            // edge to the nose; 5 cm is the upper end, as on most 9-foot tables.
            .width = 0.05,
            // The cushion's top meets the wood 1.2 mm (the cloth and the feather strip) below
            // the rail cap's top.
            .top_rise = 0.0108,
            // A K-66 cushion's face slopes back from the nose to its foot, 13.5 mm behind it.
            .undercut = 0.0135,
        },
    .rail =
        {
            // WPA: the rail, cushion included, is 4 to 7 1/2 in (10.2 to 19.1 cm) wide; a 13 cm
            // cap makes 18 cm (7.1 in) with the cushion, the width of heavy 9-foot tables.
            .width = 0.13,
            // The rail cap stands 12 mm above the nose, 48 mm (1.9 in) above the bed (the WPA
            // gives no figure).
            .top_rise = 0.012,
        },
    .sights =
        {
            // WPA: 18 sights, 12 1/2 in apart on a 9-foot table: eighths of the long side (the
            // middle one is the side pocket) and quarters of the short side.
            .long_spaces = 8,
            .short_spaces = 4,
            // WPA: each sight's centre is 3 11/16 in (93.7 mm) from the cushion's nose.
            .from_nose = 0.0937,
            // WPA: a diamond sight is 1 x 7/16 in to 1 1/4 x 5/8 in; 28 x 14 mm lies between.
            .length = 0.028,
            .width = 0.014,
        },
    .jaws =
        {
            // WPA: "the cut angles of the rubber cushion and its wood backing (rail liner) for both
            // sides of the corner pocket entrance must be 142 degrees (+-1)", of the side pocket
            // entrance 104 degrees (+-1); the angle lies between the nose and the facing, inside the
            // cushion. Corner facings so close in by 7 degrees each, side ones by 14: every throat
            // is narrower than its mouth.
            .corner_facing_deg = 142,
            .side_facing_deg = 104,
            // The slate's holes of Dr. Dave Alciatore's pocket models (TP 3.6 corner 2.75 in, TP 3.5
            // side 3 in in radius); the WPA and BCA give the shelf in front of the hole, not the hole.
            .corner_hole = 0.06985,
            .side_hole = 0.0762,
            // A table of the scene's own cushions keeps simple drop circles at the standard places,
            // 16 and 13 cm across.
            .bare_corner_radius = 0.08,
            .bare_side_radius = 0.065,
            .side_within_deg = 10,
            .near_end = 0.01,
            // Leather liners are 5 to 8 mm; BCA pocket specifications: the slate's drop point is
            // rounded to a 1/8 to 1/4 in radius under the cloth.
            .liner = 0.006,
            .lip_round = 0.005,
        },
};

/// The lamp over the table: a long open-bottomed shade hung over the middle of the noses, as long as
/// a share of the noses' length (never shorter than a minimum) and as wide everywhere.
struct LampSpec {
  double bottom = 0;           ///< m above the bed, the shade's rim
  double height = 0;           ///< m, from the rim to the shade's top
  double half_width = 0;       ///< m, half the shade across y
  double length_share = 0;     ///< the shade's half length along x over the noses' length
  double min_half_length = 0;  ///< m, the shade's half length on a short table
  double wall = 0;             ///< m, the shade's sheet, seen from below
  double cord_radius = 0;      ///< m, the cord from the shade's top to the ceiling
  double taper = 0;            ///< m the shade's sides are drawn in on each side, rim to eaves
  double roof_pitch_deg = 0;   ///< from the eaves a hipped roof rises to a ridge along the lamp
  /// Degrees from straight down: the light's cone, full within hotspot_deg and fading to nothing at
  /// falloff_deg (the shade cuts it off), as a spotlight's radius and falloff.
  double hotspot_deg = 0;
  double falloff_deg = 0;
};

/// The room the table stands in: the floor is the table's bed_height below the bed.
struct RoomSpec {
  double ceiling = 0;  ///< m above the bed
  double margin = 0;   ///< m from the table's outer edge to the walls
  LampSpec lamp;
};

inline constexpr RoomSpec kRoom{
    .ceiling = 2.6,
    .margin = 3.5,
    .lamp =
        {
            // Its rim 1.05 m above the bed (about 1.8 m above the floor): low enough to light the
            // cloth evenly, high enough to see under from a player's eye.
            .bottom = 1.05,
            .height = 0.2,  // the sides and the hipped roof over them
            .half_width = 0.22,
            .length_share = 0.3,
            .min_half_length = 0.3,
            .wall = 0.02,
            .cord_radius = 0.006,
            .taper = 0.07,
            .roof_pitch_deg = 28,
            .hotspot_deg = 24,
            .falloff_deg = 60,
        },
};

/// m, the standard nose height above the bed (what a `rail` line usually gives as z).
inline constexpr double kStandardNoseHeight = kStandardTable.nose_height;

/// An axis-aligned rectangle on the bed plane, m.
struct TableRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  TableRect grown(double by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
};

/// One diamond sight: its centre on the wood's top and which way its long diagonal runs.
struct SightPlace {
  Vec3 centre{0, 0, 0};  ///< m; z is the wood's top
  bool along_x = true;   ///< on a long side (the diamond's length along x), else on a short side
};

/// Whether a pocket opens between two cushions meeting at an angle, between two on one line, or where
/// no two cushion ends meet (then its opening is its drop circle).
enum class PocketKind { corner, side, bare };

/// One pocket as the physics and both front ends build it, seen from above (z = 0). A standard pocket
/// (corner or side, cut as the WPA's are): two jaws, each a jaw point on a cushion's nose rounded to
/// `round_radius`, and a facing running from it into the pocket at the WPA angle; the shelf between the
/// facings; the hole in the slate (its drop circle) behind it, which the throat through the wood ends in.
/// The physics meets the facings and the rounded jaw points as cushions and drops a ball whose centre
/// crosses the drop circle. A bare pocket (a scene's own `pocket` line) is its drop circle alone; the
/// pictures still cut the cushion ends near it along facings, which the physics does not see. Below
/// the bed a cup (a leather drop pocket) under the hole and the throat holds the pocketed balls.
struct PocketMouth {
  PocketKind kind = PocketKind::bare;
  bool cut = false;               ///< a real pocket's jaws the physics meets (else: drawn only, or none)
  Vec3 centre{0, 0, 0};           ///< the drop circle's centre: the hole in the slate
  double drop_radius = 0;         ///< m, the drop circle
  double facing_deg = 0;          ///< the WPA facing angle of its kind (0 for a bare pocket)
  int rail[2] = {-1, -1};         ///< the scene's rails whose ends are the jaws
  bool at_b[2] = {false, false};  ///< the jaw is that rail's b end (else its a end)
  Vec3 nose[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};    ///< the jaw points, where the nose turns into the pocket
  Vec3 facing[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};  ///< unit, along each facing from its jaw point into the rail
  Vec3 inward[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};  ///< unit, each facing's normal pointing into the opening
  Vec3 axis{1, 0, 0};                               ///< unit, from the mouth into the pocket
  Vec3 throat_centre{0, 0, 0};  ///< the round back of the throat (the drop circle's centre for a bare pocket)
  double throat_radius = 0;     ///< m
  Vec3 tangent[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};  ///< where each facing meets the round back
  // A cut pocket's jaws as the physics meets them:
  double round_radius = 0;                                ///< m, each jaw point's rounding
  Vec3 round_centre[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};  ///< its centre, inside the cushion
  Vec3 nose_end[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};      ///< where the rounding leaves the nose line
  Vec3 face_start[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};    ///< where it meets the facing

  bool jawed() const { return kind != PocketKind::bare; }
  /// rad the facing turns from the nose's direction into the pocket: 180 degrees less the facing angle.
  double turn() const { return radians(180 - facing_deg); }
  /// m between the jaws' nose ends (what the WPA calls the mouth).
  double mouth() const { return jawed() ? (nose[1] - nose[0]).norm() : 2 * drop_radius; }
  /// m from the mouth line's middle to the slate's edge along the axis (a cut pocket's shelf).
  double shelf() const { return (centre - (nose[0] + nose[1]) / 2).dot(axis) - drop_radius; }
  /// A cut pocket's facing `i` as the physics meets it: a nose line at `nose_height` from where the
  /// rounding meets it back to the hole, its playing side (the opening) on the right of a -> b, as a
  /// rail's.
  Rail facing_line(int i, double nose_height) const;
  /// Whether plan point p (z ignored) lies in the opening the jaws and the throat leave, grown by `grow`
  /// m: between the facings behind the mouth, or in the round back.
  bool in_throat(const Vec3& p, double grow = 0) const;
};

/// How one end of a cushion is cut: square (no pocket) or along a jaw's facing.
struct CushionEnd {
  int pocket = -1;   ///< the pocket whose jaw it is, or -1
  double slant = 0;  ///< m the facing runs on past the nose end per metre behind the nose (cot of the turn)
};

/// Where the standard cushion, wood, sights and lamp stand around one scene's nose lines: what both front
/// ends build their table from.
struct TableLayout {
  TableRect noses;         ///< the nose lines' bounding box (the standard bed's when there are none)
  TableRect wood_inner;    ///< where the wood begins: the noses grown by the cushion's width
  TableRect wood_outer;    ///< the table's outer edge: grown further by the wood's width
  double nose_height = 0;  ///< m, the highest nose (the standard one when there are none)
  double cushion_top = 0;  ///< m above the bed, the cushions' top where it meets the wood
  double rail_top = 0;     ///< m above the bed, the wood's top
  double floor = 0;        ///< m, the floor's z (below the bed)
  TableRect lamp;          ///< the lamp's shade seen from above, over the middle of the noses
  double lamp_bottom = 0;  ///< m above the bed, the shade's rim
  double lamp_top = 0;     ///< m above the bed, the shade's top
  std::vector<SightPlace> sights;
  std::vector<PocketMouth> pockets;  ///< one a scene's pocket, in its order
  std::vector<CushionEnd> ends_a;    ///< how each scene rail's a end is cut
  std::vector<CushionEnd> ends_b;    ///< and its b end
};

/// The pocket's jaws, throat and cup: a cut pocket's from its own jaw points and the rails that end at
/// them; a bare pocket's drawn around its drop circle from the nose ends near it.
PocketMouth pocket_mouth(const Pocket& pocket, const std::vector<Rail>& rails);

TableLayout table_layout(const Scene& scene);

}  // namespace bsim
