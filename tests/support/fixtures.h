#pragma once
// Scene texts that several tests build on. Constants are plain character arrays (constant-initialised,
// so a test's own namespace-scope constant may be built from them); a scene's line numbers are fixed
// by the text, and tests that check a reported line depend on them.
#include <initializer_list>
#include <string>
#include <string_view>

namespace bsim::test::fixtures {

/// The cue ball sent at 2.5 m/s into a small cluster of three balls (1, 9 turned on its side, 8):
/// several collisions and cushions within a few seconds. The cue line and four ball lines, no camera.
inline constexpr const char* kClusterBalls =
    "cue 0 0\n"
    "ball 0  -0.6 0.0  0.028575   2.5 0 0   1 0 0 0\n"
    "ball 1   0.2 0.01 0.028575   0 0 0     1 0 0 0\n"
    "ball 9   0.3 0.05 0.028575   0 0 0     0.7071 0.7071 0 0\n"
    "ball 8   0.3 -0.04 0.028575  0 0 0     1 0 0 0\n";

/// The cue ball at 1.6 m/s into one object ball just off its line: a hit (event 2), then cushions.
/// The cue line and two ball lines, no camera.
inline constexpr const char* kTwoBalls =
    "cue 0 0\n"
    "ball 0  -0.75 0.0  0.028575   1.6 0 0   1 0 0 0\n"
    "ball 1   0.25 0.02 0.028575   0 0 0     1 0 0 0\n";

/// The cue ball alone, sent at 1 m/s along +x from left of the table's centre. The cue line and one
/// ball line, no camera.
inline constexpr const char* kOneBall = "cue 0 0\nball 0 -0.5 0 0.028575 1 0 0 1 0 0 0\n";

/// The camera most tests need: from event 0 on, hover at (0, -3, 2), over the near long side,
/// looking at the table's centre (so +x is the right of the picture). Three lines.
inline constexpr const char* kHoverCamera = "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\nendcamera\n";

/// A camera block: `camera`, one line per description (`event ...`), `endcamera`.
std::string camera(std::initializer_list<std::string_view> descriptions);

/// kClusterBalls filmed from a hover over the near left corner, then from event 2 by a follow camera
/// on the cue ball.
std::string cluster_scene();

/// kTwoBalls filmed from a hover behind the cue ball, then from the cue strike (event 1) by a follow camera
/// on the cue ball; `more` descriptions follow those two.
std::string two_ball_scene(std::initializer_list<std::string_view> more = {});

}  // namespace bsim::test::fixtures
