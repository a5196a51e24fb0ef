#pragma once
// Physical constants of a scene, overridable with `param <name> <value>`. SI units.
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bsim {

struct PhysicsParams {
  double ball_radius = 0.028575;  ///< m (2 1/4 in pool ball)
  double ball_mass = 0.170097;    ///< kg (6 oz)
  double g = 9.81;                ///< m/s^2
  double mu_slide = 0.2;          ///< ball-cloth sliding friction (pooltool, Marlow)
  double mu_roll = 0.01;          ///< rolling resistance: a rolling ball decelerates at mu_roll*g
  double mu_spin = 0.0127;        ///< spin about z decays at 5*mu_spin*g/(2R) rad/s^2 (pooltool)
  double e_ball = 0.95;           ///< ball-ball restitution (pooltool)
  /// Ball-ball friction (spin transfer and throw): a constant when set (`param mu_ball`), else the
  /// speed-dependent TP A-14 fit, ball_friction().
  std::optional<double> mu_ball;
  double e_rail = 0.85;          ///< ball-cushion restitution (pooltool)
  double mu_rail = 0.2;          ///< ball-cushion friction (pooltool)
  double cue_mass = 0.54;        ///< kg, the stick (a 19 oz playing cue: 0.54-0.57 kg, Shepard 2009)
  double e_tip = 0.75;           ///< tip-ball restitution (Alciatore TP A-30: 0.71-0.75, medium tips)
  double cue_end_mass = 0.0057;  ///< kg, the shaft's effective end mass for squirt (TP A-31; 0: none)
  /// N/m^1.5, Hertz stiffness of two balls in contact, F = k_hertz * overlap^1.5 (Hertz 1882):
  /// (4/3) E* sqrt(R*) for phenolic resin (E = 5.84 GPa, nu = 0.34) and 57.15 mm balls.
  double k_hertz = 5.26e8;

  // The standard table's pockets (table.h, pocket_mouth): a scene's own `pocket` lines have none of these.
  // WPA equipment specifications: a corner mouth is 4.5 to 4.625 in between the jaw points, a side mouth
  // 5 to 5.125 in; these are the mouths of Dr. Dave Alciatore's pocket models (TP 3.6 corner 4.5875 in,
  // TP 3.5 side 5.0625 in), so the effective targets can be read against his tables.
  double corner_mouth = 0.1165225;  ///< m between a corner pocket's jaw points (4.5875 in)
  double side_mouth = 0.1285875;    ///< m between a side pocket's jaw points (5.0625 in)
  /// m, the shelf: from the mouth line's middle to the slate's edge along the pocket's axis. BCA pocket
  /// specifications: corner 1 5/8 to 1 7/8 in (the least of it here), side 0 to 3/8 in (TP 3.5's 3/16 in).
  double corner_shelf = 0.041275;
  double side_shelf = 0.0047625;
  /// m, the rounding of each jaw point, where the cushion's nose turns into the facing: the cloth's wrap
  /// over the cut rubber (pooltool's cushion nose radius, 5 mm; Dr. Dave's models take a sharp point).
  double jaw_radius = 0.005;

  /// Ball-ball friction coefficient at a relative slip speed of the contact points (m/s): mu_ball when
  /// set, else Alciatore's fit to measured throw, TP A-14 ("Throw", billiards.colostate.edu; also
  /// pooltool's default ball-ball resolver): 9.951e-3 + 0.108 exp(-1.088 v).
  /// Whether ball-ball contacts have friction at all: always, unless a scene sets mu_ball to 0.
  bool has_ball_friction() const { return !mu_ball || *mu_ball > 0; }
  double ball_friction(double slip_speed) const {
    return mu_ball ? *mu_ball : 9.951e-3 + 0.108 * std::exp(-1.088 * slip_speed);
  }
  /// Deceleration of a rolling ball, m/s^2.
  double roll_decel() const { return mu_roll * g; }
  /// Angular deceleration of spin about the vertical axis, rad/s^2.
  double spin_decel() const { return 5.0 * mu_spin * g / (2.0 * ball_radius); }
  bool operator==(const PhysicsParams&) const = default;
};

/// What a `param` name does to PhysicsParams; nullopt for an unknown name.
struct ParamSpec {
  std::string_view name;
  std::string_view unit;
  std::string_view meaning;
  double min;  ///< smallest physical value (inclusive unless min_exclusive)
  bool min_exclusive;
  double max;  ///< largest physical value (inclusive)
};

/// Every `param` name, in the order the documentation lists them.
const std::vector<ParamSpec>& param_specs();
/// The spec of a `param` name; nullopt for an unknown name.
std::optional<ParamSpec> find_param(std::string_view name);
/// Whether `value` lies in the spec's physical range.
bool param_in_range(const ParamSpec& spec, double value);
/// The physical range in words, e.g. "greater than 0" or "from 0 to 1".
std::string describe_range(const ParamSpec& spec);
/// Sets the named constant (`table_speed` sets mu_roll = 1 / value). Unknown names are ignored.
void apply_param(PhysicsParams& params, std::string_view name, double value);

}  // namespace bsim
