#include <cmath>
#include <limits>

#include "physics_params.h"

namespace bsim {

namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// The friction coefficients that bring a ball to rest must be positive, or a shot never ends.
const std::vector<ParamSpec> kSpecs = {
    {"ball_radius", "m", "radius of every ball", 0, true, kNoLimit},
    {"ball_mass", "kg", "mass of every ball", 0, true, kNoLimit},
    {"g", "m/s^2", "gravitational acceleration", 0, true, kNoLimit},
    {"mu_slide", "", "ball-cloth sliding friction coefficient", 0, true, kNoLimit},
    {"mu_roll", "", "rolling resistance: a rolling ball decelerates at mu_roll*g", 0, true, kNoLimit},
    {"mu_spin", "", "spin about the vertical decays at 5*mu_spin*g/(2*ball_radius) rad/s^2", 0, true, kNoLimit},
    {"e_ball", "", "ball-ball coefficient of restitution", 0, false, 1},
    {"mu_ball", "", "ball-ball friction coefficient (spin transfer and throw); unset: TP A-14 speed fit", 0, false,
     kNoLimit},
    {"e_rail", "", "ball-cushion coefficient of restitution", 0, false, 1},
    {"mu_rail", "", "ball-cushion friction coefficient", 0, false, kNoLimit},
    {"k_hertz", "N/m^1.5", "Hertz contact stiffness of two balls, F = k_hertz*overlap^1.5", 0, true, kNoLimit},
    {"cue_mass", "kg", "mass of the stick (stroke)", 0, true, kNoLimit},
    {"e_tip", "", "tip-ball coefficient of restitution (stroke)", 0, false, 1},
    {"cue_end_mass", "kg", "the stick's effective end mass, which sets the squirt (stroke; 0: none)", 0, false,
     kNoLimit},
    {"corner_mouth", "m", "the standard table's corner pockets: between the jaw points (WPA 4.5-4.625 in)", 0, true,
     kNoLimit},
    {"side_mouth", "m", "the standard table's side pockets: between the jaw points (WPA 5-5.125 in)", 0, true,
     kNoLimit},
    {"corner_shelf", "m", "the corner pockets' shelf, from the mouth line to the hole (BCA 1 5/8-1 7/8 in)", 0, false,
     kNoLimit},
    {"side_shelf", "m", "the side pockets' shelf, from the mouth line to the hole (BCA 0-3/8 in)", 0, false, kNoLimit},
    {"jaw_radius", "m", "the rounding of the standard pockets' jaw points", 0, false, kNoLimit},
    {"table_speed", "", "the seed's table speed: sets mu_roll to 1/table_speed", 0, true, kNoLimit},
};

std::string number_text(double v) {
  std::string s = std::to_string(v);  // fixed, six decimals; trim the zeros for messages
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

const std::vector<ParamSpec>& param_specs() { return kSpecs; }

std::optional<ParamSpec> find_param(std::string_view name) {
  for (const ParamSpec& spec : kSpecs)
    if (spec.name == name) return spec;
  return std::nullopt;
}

bool param_in_range(const ParamSpec& spec, double value) {
  if (!std::isfinite(value)) return false;
  if (spec.min_exclusive ? value <= spec.min : value < spec.min) return false;
  return value <= spec.max;
}

std::string describe_range(const ParamSpec& spec) {
  if (std::isinf(spec.max)) return (spec.min_exclusive ? "greater than " : "at least ") + number_text(spec.min);
  return (spec.min_exclusive ? "greater than " + number_text(spec.min) + " and at most "
                             : "from " + number_text(spec.min) + " to ") +
         number_text(spec.max);
}

void apply_param(PhysicsParams& p, std::string_view name, double value) {
  if (name == "ball_radius")
    p.ball_radius = value;
  else if (name == "ball_mass")
    p.ball_mass = value;
  else if (name == "g")
    p.g = value;
  else if (name == "mu_slide")
    p.mu_slide = value;
  else if (name == "mu_roll")
    p.mu_roll = value;
  else if (name == "mu_spin")
    p.mu_spin = value;
  else if (name == "e_ball")
    p.e_ball = value;
  else if (name == "mu_ball")
    p.mu_ball = value;
  else if (name == "e_rail")
    p.e_rail = value;
  else if (name == "mu_rail")
    p.mu_rail = value;
  else if (name == "k_hertz")
    p.k_hertz = value;
  else if (name == "cue_mass")
    p.cue_mass = value;
  else if (name == "e_tip")
    p.e_tip = value;
  else if (name == "cue_end_mass")
    p.cue_end_mass = value;
  else if (name == "corner_mouth")
    p.corner_mouth = value;
  else if (name == "side_mouth")
    p.side_mouth = value;
  else if (name == "corner_shelf")
    p.corner_shelf = value;
  else if (name == "side_shelf")
    p.side_shelf = value;
  else if (name == "jaw_radius")
    p.jaw_radius = value;
  else if (name == "table_speed")
    p.mu_roll = 1.0 / value;
}

}  // namespace bsim
