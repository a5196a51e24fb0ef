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
