#pragma once
// The `rack` extension: a game's object balls racked as a real rack racks them. Each ball's diameter is
// drawn within the WPA equipment tolerance (2 1/4 in +- 0.005 in, WPA "Equipment Specifications",
// Balls), the apex ball sits on the foot spot, and the rest are pushed toward the apex as the frame
// pushes them: each settles as far forward as the balls in front and the frame's sides let it. A set of
// balls that differ by a few hundredths of a millimetre cannot all touch, so the rack keeps the small
// gaps every real rack has. The physics keeps one nominal radius: no two centres come closer than two
// nominal radii (two undersized balls meet at the nominal distance), so nothing overlaps.
// `tight` is the mathematical rack: every ball of the nominal size, every neighbour touching.
// Everything random comes from one splitmix64 stream (written out here, not std:: distributions, whose
// output differs between standard libraries) and the arithmetic is +, -, *, / and sqrt, so a seed
// gives the same rack, to the bit, everywhere.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace bsim {

enum class RackGame { eight_ball, nine_ball, ten_ball };

/// The game a `rack` line names ("8ball", "9ball", "10ball"), or nothing.
std::optional<RackGame> rack_game(std::string_view name);
std::string_view rack_game_name(RackGame game);
/// The game names, for messages and "did you mean".
inline constexpr std::array<std::string_view, 3> kRackGameNames = {"8ball", "9ball", "10ball"};

/// How many object balls the game racks: 15, 9 or 10, painted 1 to that number.
int rack_ball_count(RackGame game);

/// The foot spot, where the apex ball's centre sits, m (the standard table's, spec.md).
inline constexpr double kFootSpotX = 0.635;
inline constexpr double kFootSpotY = 0.0;
/// WPA ball tolerance, as a fraction of the diameter: 0.005 in of 2.25 in.
inline constexpr double kBallDiameterTolerance = 0.005 / 2.25;

struct RackSpec {
  RackGame game = RackGame::eight_ball;
  std::uint64_t seed = 0;
  bool tight = false;
  double radius = 0.028575;                   ///< the physics' nominal ball radius, m
  double tolerance = kBallDiameterTolerance;  ///< diameters within +- this fraction (larger: pictures only)
};

struct RackedBall {
  int number = 0;       ///< painted number, 1 to rack_ball_count
  int row = 0;          ///< 0 at the apex, counting toward the foot rail
  int column = 0;       ///< 0 at -y within the row
  double x = 0, y = 0;  ///< centre on the table, m
  double diameter = 0;  ///< the drawn diameter, m (2 * radius when tight)
};

/// The game's balls in order of painted number. The apex is on the foot spot; the rack opens toward +x.
std::vector<RackedBall> rack_balls(const RackSpec& spec);

/// splitmix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014; the
/// constants of Vigna's reference code): a 64-bit state stepping by the golden gamma.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [0, n), without modulo bias (rejection of the short last stretch).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t v = next();
    while (v >= limit) v = next();
    return v % n;
  }

 private:
  std::uint64_t state_;
};

}  // namespace bsim
