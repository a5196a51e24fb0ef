#pragma once
// Numbered events of a shot (what the camera script and the sound track synchronise to).
#include <string_view>
#include <vector>

#include "ball_state.h"

namespace bsim {

enum class EventType { start, cue, ball_ball, ball_rail, ball_jaw, end };

/// The name used in events.json: "start", "cue", "ball-ball", "ball-rail", "ball-jaw", "end".
std::string_view to_string(EventType type);

/// One contact of a group collision (several balls in contact resolved together, group.h).
struct Contact {
  int a = 0, b = 0;     ///< file-order indices, a < b
  double time = 0;      ///< s, when the contact began (the group's instant plus its place in the phase)
  double speed = 0;     ///< m/s, the largest closing speed the contact reached
  Vec3 where{0, 0, 0};  ///< m, the contact point
  bool operator==(const Contact&) const = default;
};

struct Event {
  int index = 0;    ///< position in Timeline::events(), 0 = start
  double time = 0;  ///< s
  EventType type = EventType::start;
  /// file-order indices: cue [target], ball-ball [i, j, ...] ascending, ball-rail and ball-jaw [i]
  std::vector<int> balls;
  int rail = -1;        ///< ball-rail: index into Scene::rails; ball-jaw: the rail whose end is the jaw
  int pocket = -1;      ///< ball-jaw: index into Scene::pockets (a facing or a rounded jaw point of its jaws)
  double speed = 0;     ///< m/s, closing speed along the contact normal (cue: the ball's speed)
  Vec3 where{0, 0, 0};  ///< m, the contact point (cue: the struck ball's centre)
  std::vector<BallState> before, after;  ///< states of `balls` just before and after
  /// ball-ball: its contacts in the order they began: a pair resolved alone has one (the event's own
  /// time, speed and point), a group collision one per contact, `balls` then listing every ball of the
  /// group and `speed` being the largest contact speed.
  std::vector<Contact> contacts;
  bool grouped = false;  ///< ball-ball: resolved as a group collision (group.h), not as a pair alone
  int shot = 0;          ///< the shot it belongs to, from 0 (Scene::cues); the start event is the first's
  bool operator==(const Event&) const = default;
};

/// One shot's stretch of the timeline: the stick comes in from `start`, strikes at `cue`, and every ball
/// is at rest (on the bed or down a pocket) from `rest`.
struct ShotSpan {
  double start = 0;  ///< s; the first shot's is 0, a later one's a moment after the shot before rests
  double cue = 0;    ///< s, the strike
  double rest = 0;   ///< s
  bool operator==(const ShotSpan&) const = default;
};

/// A ball dropping into a pocket: recorded, but not a numbered event (as in the seed).
struct PocketDrop {
  double time = 0;  ///< s, when the ball's centre crosses into the pocket
  int ball = 0;     ///< file-order index
  int pocket = 0;   ///< index into Scene::pockets
  bool operator==(const PocketDrop&) const = default;
};

}  // namespace bsim
