#include "hertz.h"

#include <cmath>

namespace bsim {

double hertz_stiffness(double young_modulus, double poisson, double ball_radius) {
  const double modulus = young_modulus / (2 * (1 - poisson * poisson));
  return 4.0 / 3.0 * modulus * std::sqrt(ball_radius / 2);
}

double hertz_compression(double speed, const HertzPair& pair) {
  const double reduced_mass = 0.5 * pair.ball_mass;
  return std::pow(5.0 * reduced_mass * speed * speed / (4.0 * pair.stiffness), 0.4);
}

double hertz_compression(double speed, const PhysicsParams& params) {
  return hertz_compression(speed, hertz_pair(params));
}

double hertz_contact_time(double speed, const HertzPair& pair, double time_factor) {
  return time_factor * hertz_compression(speed, pair) / speed;
}

double hertz_contact_time(double speed, const PhysicsParams& params) {
  return hertz_contact_time(speed, hertz_pair(params));
}

}  // namespace bsim
