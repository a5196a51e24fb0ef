#pragma once
// The parsed scene: plain values in SI units with every default filled in. Each entity keeps the
// source location of its tokens so that checks made after simulation can still cite the file.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check.h"
#include "physics_params.h"
#include "rack.h"
#include "source_loc.h"
#include "table.h"
#include "vec.h"

namespace bsim {

struct Ball {
  int number = 0;                       ///< painted number, 0 (cue ball) to 15
  Vec3 position{0, 0, 0};               ///< m, centre; z = ball radius on the bed
  Vec3 velocity{0, 0, 0};               ///< m/s, given to the ball at the cue impact
  Vec3 spin{0, 0, 0};                   ///< rad/s, angular velocity given at the cue impact (`spin` extension)
  Quat orientation = Quat::Identity();  ///< normalised
  SourceLoc loc;                        ///< the `ball` keyword
  /// A later shot's scene (play.h) only: the pocket this ball lies in, put down by an earlier shot; -1
  /// for a ball on the bed. A scene file never sets it.
  int pocket = -1;
};

/// A cushion's nose line, clockwise seen from above: the playing side is on the right from a to b.
struct Rail {
  Vec3 a{0, 0, 0};  ///< m; z is the nose height above the bed
  Vec3 b{0, 0, 0};
  SourceLoc loc;
};

/// A pocket: the hole a ball drops through (its drop circle). The standard table's are cut as real ones
/// (table.h, PocketMouth): two jaws on the cushions' ends and a shelf in front of the hole. A scene's own
/// `pocket` line is a hole alone.
struct Pocket {
  Vec3 center{0, 0, 0};  ///< m, on the bed plane: the hole's centre
  double radius = 0;     ///< m, the hole's
  SourceLoc loc;
  bool cut = false;                              ///< jaws and a shelf, as the standard table's
  PocketKind kind = PocketKind::bare;            ///< cut: a corner or a side pocket
  Vec3 jaw[2] = {Vec3(0, 0, 0), Vec3(0, 0, 0)};  ///< cut: the jaw points, where rails end
  Vec3 axis{1, 0, 0};                            ///< cut: unit, from the mouth into the pocket
  double jaw_radius = 0;                         ///< cut: m, each jaw point's rounding
};

/// A `stroke` line (extension): how the stick meets the struck ball. The ball's velocity and spin
/// follow from it (core/physics/strike.h).
struct Stroke {
  static constexpr double kMaxSpeed = 15;       ///< m/s, the fastest stroke accepted
  static constexpr double kMiscueOffset = 0.5;  ///< fraction of R: further out the tip miscues
  double speed = 0;                             ///< m/s, the tip's speed at impact, in (0, kMaxSpeed]
  double side = 0;           ///< fraction of R across the stick, > 0 right of centre as the shooter sees it
  double height = 0;         ///< fraction of R across the stick, > 0 above centre
  double elevation_deg = 0;  ///< degrees the butt is raised above level, [0, 90)
  SourceLoc loc;             ///< the `stroke` keyword
  SourceLoc speed_loc, side_loc, elevation_loc;
};

/// A `place` line (extension) under a later shot's `cue` line: before that shot, ball `ball` is put at
/// rest at `at`, or, without coordinates, where its `ball` line (or the rack) first put it.
struct BallPlacement {
  int ball = -1;           ///< file-order index
  std::optional<Vec3> at;  ///< m on the bed (z = ball radius), or none: the ball's starting place
  SourceLoc loc;           ///< the `place` keyword
  SourceLoc ball_loc, at_loc;
};

/// One shot: a `cue` line and the lines under it that belong to it (its `stroke`, its `place` lines).
struct Cue {
  int target = 0;          ///< file-order index of the struck ball
  double heading_deg = 0;  ///< direction the stick pushes, counter-clockwise from +x (found by aiming for `pot`)
  SourceLoc loc;           ///< the `cue` keyword
  SourceLoc target_loc;
  SourceLoc heading_loc;
  /// Aim extension, `cue I pot B P`: the heading is to be found (aim.h) so that ball B drops into pocket P.
  int pot_ball = -1;  ///< file-order index, or -1 when the line gives a heading
  int pot_pocket = -1;
  SourceLoc pot_ball_loc, pot_pocket_loc;
  bool aims() const { return pot_ball >= 0; }
  /// Games: `cue I H call B P`, `call safety`, `call push-out` after a heading: what the shooter called
  /// (the rules of 8-ball judge a shot by its call; a written `pot` calls its ball and pocket).
  int call_ball = -1;  ///< file-order index, or -1
  int call_pocket = -1;
  bool call_safety = false;
  bool call_push_out = false;
  SourceLoc call_loc;
  std::optional<Stroke> stroke;       ///< the `stroke` line; without one the ball lines give the velocities
  std::vector<BallPlacement> places;  ///< a later shot's `place` lines, in file order
};

/// A `player <name> [noise <k>]` line (games): one of the two players, in order of play.
struct PlayerLine {
  std::string name;
  double noise = 1;  ///< times the Computational Pool Olympiad's standard deviations (0: as planned)
  SourceLoc loc, noise_loc;
};

/// A `game <rules> [seed <n>] [shots <m>]` line (extension): the scene is a game, played by the rules
/// and, where no `cue` line says what to do, by the program's players (core/game/).
struct GameLine {
  static constexpr int kDefaultShots = 60;
  RackGame rules = RackGame::nine_ball;  ///< 9ball or 8ball
  std::uint64_t seed = 0;                ///< the rack's and the players' seed
  int shots = kDefaultShots;             ///< the most shots played (the game then ends with no winner)
  SourceLoc loc, rules_loc, seed_loc, shots_loc;
  std::vector<PlayerLine> players;  ///< as written: none, one or two (the rest are "Player 1", "Player 2")
};

enum class CameraMode { hover, look, follow };

/// What a camera description starts at: the seed's event number, or a key naming a moment of the
/// shot (extensions): start, cue, end, [ordinal] hit I J, [ordinal] cushion I, [ordinal] jaw I (a
/// pocket's jaw, not a rail), drop I (older spelling pocket I), at T, each
/// optionally after `shot K` to count within the K-th shot.
enum class CameraKeyKind { event, start, cue, end, hit, cushion, drop, at, jaw };

struct CameraKey {
  static constexpr int kLast = -1;  ///< ordinal of `last`
  CameraKeyKind kind = CameraKeyKind::event;
  int ordinal = 1;         ///< hit/cushion/jaw: 1 (the first) to 5 (`fifth`), or kLast
  int a = -1, b = -1;      ///< hit: the two balls as written; cushion/jaw/drop: the ball in a (file-order indices)
  double seconds = 0;      ///< at: s after the start of the shot (as text: camera_key_text.h)
  SourceLoc a_loc, b_loc;  ///< the ball index tokens
  /// `shot K` before the key (an extension): the 0-based shot it counts within (K - 1); -1 without
  /// it, counting over the whole scene.
  int shot = -1;
  SourceLoc shot_loc;  ///< the shot number token after `shot`
};

/// One `event N pre post <mode> ...` line of the camera script.
struct CameraShot {
  static constexpr int kLastEvent = 65535;  ///< the seed's magic number for "the last event"
  int event = 0;                            ///< event number, or kLastEvent (key.kind == event)
  CameraKey key;                            ///< what the description starts at when it is not a number
  double pre = 0;                           ///< fraction of the span from the previous listed event, [0, 1]
  double post = 0;                          ///< fraction of the span to the next listed event, [0, 1]
  CameraMode mode = CameraMode::hover;
  Vec3 location{0, 0, 0};  ///< hover/look: world position; follow: offset in the ball's frame
  Vec3 target{0, 0, 0};    ///< hover: the point looked at
  int ball = -1;           ///< look/follow: file-order index of the ball
  SourceLoc loc;           ///< the `event` keyword
  SourceLoc event_loc;     ///< the event number token (a key's first token)
  SourceLoc ball_loc;      ///< the ball index token (look/follow)
};

struct Scene {
  std::string name = "scene";  ///< file stem, used for the default output directory
  /// The shots, one per `cue` line in file order (at least one in a parsed scene but a game's, which
  /// may have none). The first is struck
  /// from the `ball` lines' velocities or its stroke; each later one, with its stroke, from where the
  /// shot before left the balls (play.h). A scene built in code starts with one cue, ball 0 at heading 0.
  std::vector<Cue> cues{Cue{}};
  std::vector<Ball> balls;      ///< file order
  std::vector<Rail> rails;      ///< file order, or the standard table's six cushions
  std::vector<Pocket> pockets;  ///< file order, or the standard table's six pockets
  std::vector<CameraShot> camera;
  SourceLoc camera_loc;  ///< the `camera` keyword
  PhysicsParams physics;
  /// A `game` line: a game by the rules. Its `cue` lines (there may be none) are its first shots, as
  /// written; the players play on from where they leave the table.
  std::optional<GameLine> game;

  /// The first shot's cue: the only one of a scene of one shot.
  const Cue& cue() const {
    BSIM_EXPECT(!cues.empty(), "a scene without a cue");
    return cues.front();
  }
  Cue& cue() {
    BSIM_EXPECT(!cues.empty(), "a scene without a cue");
    return cues.front();
  }
  int shot_count() const { return static_cast<int>(cues.size()); }

  /// Ball `i` (file order); the index must be one of the scene's balls.
  const Ball& ball(int i) const {
    BSIM_EXPECT(i >= 0 && static_cast<std::size_t>(i) < balls.size(), "no such ball in the scene");
    return balls[static_cast<std::size_t>(i)];
  }
};

/// The standard 9-foot table's (kStandardTable's) cushions and pockets, in the spec's numbering.
std::vector<Rail> standard_rails(const PhysicsParams& params = {});
std::vector<Pocket> standard_pockets(const PhysicsParams& params = {});
/// The standard pockets' places as plain drop circles, for a table of the scene's own cushions.
std::vector<Pocket> bare_standard_pockets();

/// Pockets in words. The standard table's six have names by where they are (top is +y, right +x, as
/// the table is seen from above); a scene's own `pocket` lines have only their numbers.
///
/// The words a pocket number may be written as (`cue 0 pot 3 top-right`), for pocket 0 to 5 in order:
/// top-left, top-side, top-right, bottom-right, bottom-side, bottom-left; with `aliases`, then
/// top-middle and bottom-middle.
std::vector<std::string_view> standard_pocket_words(bool aliases = false);
/// The standard pocket a word names: one of standard_pocket_words(), or the alias top-middle or
/// bottom-middle (the side pockets, as the table's numbering calls them); none for any other word.
std::optional<int> standard_pocket_number(std::string_view word);
/// Whether `pockets` are the standard table's six (no `pocket` line of the scene's own).
bool standard_pocket_set(const std::vector<Pocket>& pockets);
/// A pocket as messages and pictures name it: "the top-right corner (pocket 2)", "the bottom side
/// pocket (pocket 4)" on the standard table; "pocket 7" for a scene's own pocket lines.
std::string pocket_name(const std::vector<Pocket>& pockets, int pocket);
/// The same, shorter, for a picture's small labels: "top-right corner", "bottom side"; "pocket 7".
std::string pocket_short_name(const std::vector<Pocket>& pockets, int pocket);

}  // namespace bsim
