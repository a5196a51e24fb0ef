#pragma once
// What a pool ball looks like, one description for both front ends: the standard colours (1 yellow,
// 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon, 8 black; 9 to 15 are the stripes of 1 to 7
// on white; 0 is the white cue ball). The values are sRGB bytes as a painter would pick them off a
// standard set (Aramith-style), before any lighting.
#include <cstdint>

namespace bsim {

struct SrgbColor {
  std::uint8_t r = 0, g = 0, b = 0;  ///< sRGB-encoded, 0 to 255
};

/// The white of the cue ball, the stripes' ground and the number discs: a modern set's white, a
/// hair warm (an old ivory cream reads yellow under the warm lamp).
inline constexpr SrgbColor kBallIvory{248, 247, 242};

/// The colour of the solids 1 to 8, indexed by number (index 0 is the cue ball's white).
inline constexpr SrgbColor kSolidColors[9] = {
    kBallIvory,      // 0 cue ball
    {250, 196, 18},  // 1 yellow
    {18, 52, 170},   // 2 blue
    {206, 22, 22},   // 3 red
    {86, 28, 130},   // 4 purple
    {248, 108, 16},  // 5 orange
    {10, 112, 56},   // 6 green
    {122, 22, 24},   // 7 maroon
    {14, 14, 16},    // 8 black
};

/// Whether ball `number` is a stripe (9 to 15).
constexpr bool ball_striped(int number) { return number >= 9 && number <= 15; }

/// The colour of ball `number`: a stripe shares its solid's (9 is 1's yellow, ..., 15 is 7's maroon);
/// the cue ball and any number outside 0 to 15 are ivory.
constexpr SrgbColor ball_srgb(int number) {
  if (number < 0 || number > 15) return kBallIvory;
  return kSolidColors[number <= 8 ? number : number - 8];
}

}  // namespace bsim
