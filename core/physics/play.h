#pragma once
// Several shots (`cue` lines) played in file order into one timeline. Each shot is simulated on its own
// (simulate.h) from where the shot before left the balls: a pocketed ball stays down, the `place`
// lines of the shot put balls back on the bed, and a struck ball that went down comes back on the head
// spot. A shot that aims (`cue I pot B P`) is aimed there, from those positions (aim.h). The pieces are
// then laid end to end: a later shot's stick comes in as soon as every ball of the shot before rests,
// events are numbered over the scene with one start and one end, and each shot's span is kept.
#include <optional>
#include <string>
#include <vector>

#include "scene.h"
#include "simulate.h"
#include "timeline.h"

namespace bsim {

/// The head spot, where a struck ball that went down is put back for a later shot (spec.md), m.
inline constexpr double kHeadSpotX = -0.635;
inline constexpr double kHeadSpotY = 0.0;

/// Why a shot could not be played: a `pot` with no heading from where the balls stopped, a `place`
/// that puts a ball onto another, a ball that left the table (table_escape.h; the shot is then in the
/// timeline).
struct PlayFailure {
  int shot = 0;   ///< from 0
  SourceLoc loc;  ///< the line to blame: the shot's `cue` line, or a `place` line
  std::string message;
};

/// What playing the shots found, for the scene to be filmed as played: each shot's heading (the one
/// written, or the one aiming found) and the balls as the first shot's strike left them.
struct PlayFound {
  std::vector<double> headings;  ///< per shot played, degrees
  std::vector<Ball> struck;      ///< the scene's balls with the first shot's struck ball as struck
};

struct PlayResult {
  Timeline timeline;  ///< every shot played (those before a failure)
  std::optional<PlayFailure> failure;
  PlayFound found;
};

/// The shots laid end to end, one at a time: a game adds each shot as it is decided (core/game/game.h);
/// play() adds a scene's shots in file order. Each shot is simulated on its own from where the shots
/// before left the balls.
class ShotChain {
 public:
  /// `scene` gives the table, the physics and the balls where the first shot finds them.
  explicit ShotChain(const Scene& scene);

  /// Plays shot k (the next one: k == shots()) of `scene` (whose balls, table and physics are the
  /// chain's, and whose cue k is the shot): its `place` lines, a scratched struck ball put back on the
  /// head spot, its aim, its strike and its simulation. A failure leaves the chain as it was, but for a
  /// ball off the table, whose shot is laid down for a picture of it.
  std::optional<PlayFailure> play(const Scene& scene, int k);

  int shots() const { return static_cast<int>(shots_.size()); }
  /// The balls where the shots so far left them, at rest; a ball down has Ball::pocket set.
  std::vector<Ball> standing() const;
  /// Every event and drop so far (shot-numbered, on the chain's clock; no end event yet).
  const std::vector<Event>& events() const { return events_; }
  const std::vector<PocketDrop>& drops() const { return drops_; }
  const PlayFound& found() const { return found_; }
  /// The timeline of the shots so far, with its end event.
  Timeline finish() const;

 private:
  void add(SimulationResult r, const std::vector<char>& moved, double offset, int k);

  Scene table_;  ///< the scene's table, physics and first balls; no cues
  std::vector<std::vector<MotionSegment>> segments_;
  std::vector<Event> events_;
  std::vector<PocketDrop> drops_;
  std::vector<ShotSpan> shots_;
  PlayFound found_;
};

/// Plays every shot of `scene` in file order. Each cue that aims is aimed from where the balls stood
/// before it; what was found is returned, the scene left as written. Deterministic: the same scene
/// gives the same bytes.
PlayResult play(const Scene& scene);

/// `scene` as played: each shot's heading as found and the first shot's struck ball as struck.
void write_found(Scene& scene, const PlayFound& found);

/// Where a later shot's struck ball is put back after it went down: on the head spot, or the nearest
/// place behind it on the long axis (y = 0, toward the head cushion) where it touches no ball; in front
/// of the spot when nothing behind is free. `balls` as they stand, `ball` the one to put back.
Vec3 respot_place(const Scene& scene, const std::vector<Ball>& balls, int ball);

/// Where a ball is spotted: at (x, 0), or the nearest place on the long axis that touches no ball,
/// looking first toward `first` (+1: toward +x, the foot rail; -1: toward the head rail), then the other
/// way. The rules spot the 9 (9-ball) and the 8 (8-ball) on the foot spot, behind it when taken (WPA).
Vec3 spot_place(const Scene& scene, const std::vector<Ball>& balls, int ball, double x, int first);

}  // namespace bsim
