#pragma once
// Procedural impact sounds, one mono burst per collision, synthesised from the contact it models:
// a Hertz force pulse heard as acceleration noise for ball on ball (Koss & Alfredson 1973; Chadwick,
// Zheng & James 2012), the same pulse driving a few damped modes for cushion, jaw, cue tip and the
// pocket's lip and liner (modal synthesis after van den Doel, Kry & Pai, "FoleyAutomatic", 2001), and the
// rolling model of rolling.h for a pocketed ball rolling away inside the table.
#include <cstdint>
#include <vector>

#include "physics_params.h"

namespace bsim {

enum class SoundKind {
  ball_ball,     ///< a contact between two balls
  ball_rail,     ///< a ball against a cushion
  cue,           ///< the cue tip striking the cue ball
  pocket_fall,   ///< a ball tipping over a pocket's lip into the pocket
  pocket_knock,  ///< a falling ball knocking against the pocket's liner or landing at its bottom
  pocket_roll,   ///< a pocketed ball rolling away down the table's gutter
  jaw_knock,     ///< a ball against a pocket's jaw: its facing or its rounded jaw point
};

/// A small deterministic generator (splitmix64), so sounds never depend on the standard library's
/// distributions.
class SoundRandom {
 public:
  explicit SoundRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform();  ///< [0, 1)
  double signed_unit() { return 2.0 * uniform() - 1.0; }

 private:
  std::uint64_t state_;
};

/// The seed of a knock on pocket `pocket`'s jaws: the pocket's modes (upper 32 bits), the knock's own
/// noise from `knock` (lower 32 bits).
std::uint64_t jaw_seed(int pocket, std::uint64_t knock);

/// s, the contact of a ball on a jaw's facing at `speed` m/s: hard rubber a few millimetres thick on
/// the rail's wood, about a fifth of the cushion's (shorter when faster).
double jaw_contact_time(double speed);

/// s, duration of the Hertz contact (hertz.h) a ball-ball click is made of, for two equal balls
/// closing at `speed` m/s: the physics' own contact, with the scene's ball mass and `param k_hertz`
/// (its balls' material). A stiffer or lighter ball makes a shorter click, and a brighter one: the
/// click's pulse is that short, and the ring after it weaker (sound_synth.cpp, ball_click).
double click_contact_time(const PhysicsParams& physics, double speed);

/// Peak amplitude of a sound of this kind at this speed (m/s), before panning: strictly growing
/// with speed, compressed so that a gentle touch stays audible beside a break.
double impact_gain(SoundKind kind, double speed);

/// The sound of one impact at `speed` m/s, mono at `sample_rate`, starting at sample 0 (the instant
/// of contact). Its peak is impact_gain(kind, speed). `seed` varies the modes from hit to hit; for a
/// jaw's knock its upper 32 bits choose the jaw's modes (jaw_seed: one pocket's jaws ring alike, so
/// every knock of a rattle has one character) and its lower 32 bits the knock's own noise.
std::vector<float> synth_impact(SoundKind kind, double speed, std::uint64_t seed, const PhysicsParams& physics,
                                int sample_rate);

}  // namespace bsim
