#pragma once
// Camera moments, in one place: the instants of a simulated shot a camera description can start at.
// A moment is named as the scene language names it, by a camera key (`start`, `cue`, `hit 0 5`,
// `last cushion 3`, `jaw 2`, `drop 8`, `at 2.4`, `shot 2 cue`, ...) or an event number. Here a name
// is resolved against the timeline (the instant it names, or why the shot never reaches it), the name
// of a moment is found (of a time, of an event, of a ball's first or last contact), each shot's stretch
// of the timeline is given, the contacts the keys count are walked, and a description line is written
// in the one format scene text uses. The words and shapes of keys are the scene's
// (scene/camera_key_text.h); the director, the window's camera editor and the pictures' labels all
// name, resolve and write moments through this.
#include <optional>
#include <string>
#include <vector>

#include "camera_key_text.h"
#include "scene.h"
#include "source_loc.h"
#include "timeline.h"

namespace bsim {

// --- A shot's stretch of the timeline --------------------------------------------------------------

/// One shot's stretch: the stick comes in from `start`, strikes at `strike`, every ball rests from
/// `rest`, and the stretch runs to `end`, the next shot's start (the last shot's: the end event).
struct ShotStretch {
  int shot = -1;      ///< from 0; -1: the whole scene (from 0 to the end event)
  double start = 0;   ///< s
  double strike = 0;  ///< s, the stick strikes
  double rest = 0;    ///< s
  double end = 0;     ///< s
  bool last = true;   ///< it reaches the end event (the last shot, or the whole scene)
  /// Whether t falls in it: from its start up to the next shot's start (the last: to its end, included).
  bool holds(double t) const { return t >= start && (t < end || (last && t <= end)); }
};

/// Shot `shot`'s stretch (Timeline::shots()); the whole scene's for -1 or a shot the timeline lacks.
ShotStretch shot_stretch(const Timeline& timeline, int shot);

// --- The contacts keys count ------------------------------------------------------------------------

/// One contact between two balls, as `hit` keys count them: a contact inside a group collision at
/// its own instant.
struct BallContact {
  double time = 0;   ///< s
  int event = -1;    ///< the ball-ball event it belongs to
  int a = 0, b = 0;  ///< file-order indices
  /// The ball `ball` meets.
  int other(int ball) const { return ball == a ? b : a; }
};

/// Every contact between balls in shot `shot` (-1: every shot), in time order (ties in event order);
/// only those of `ball` when it is given (>= 0), only those of `ball` with `with` when both are.
std::vector<BallContact> ball_contacts(const Timeline& timeline, int shot = -1, int ball = -1, int with = -1);

/// Every ball-rail (`cushion`) or ball-jaw (`jaw`) event of `ball` in shot `shot` (-1: every shot),
/// in time order.
std::vector<const Event*> ball_touches(const Timeline& timeline, EventType type, int ball, int shot = -1);

// --- Resolving a name -------------------------------------------------------------------------------

/// The moment a description starts at.
struct KeyInstant {
  double time = 0;  ///< s
  /// The numbered event it is or falls within (a hit inside a group: the group's event), -1 for a
  /// pocket drop or an `at` time. Orders descriptions at the same instant.
  int event = -1;
};

struct KeyResolution {
  std::optional<KeyInstant> instant;  ///< none when the shot never reaches it
  std::string problem;                ///< why not, as a message ("drop 3 never happens: ...")
  SourceLoc where;                    ///< the token the problem is about
};

/// Resolves the event number or key `shot` starts at against the simulated shot (its balls checked
/// against the scene's).
KeyResolution resolve_camera_key(const CameraShot& shot, const Scene& scene, const Timeline& timeline);

/// The instant key `key` (or, for kind event, event number `event`) names in `timeline`; none when
/// the shot never reaches it or names no such ball, shot or event.
std::optional<KeyInstant> moment_instant(const CameraKey& key, int event, const Timeline& timeline);

/// How a message names what the description starts at: "event 5" or the key ("hit 0 5").
std::string describe_camera_key(const CameraShot& shot);

/// Where a message about a camera description points: its token when it has one, else its line.
SourceLoc message_loc(const SourceLoc& token, const SourceLoc& line);

/// "7 events (0 to 6)", "1 ball (index 0)": how many there are and their indices, for messages.
std::string counted(int count, const std::string& noun);

// --- Naming a moment --------------------------------------------------------------------------------

/// A moment of the shot with its name.
struct NamedMoment {
  CameraKey key;    ///< kind event: named by its event number, `event`
  double time = 0;  ///< s, the instant the name resolves to
  int event = -1;   ///< the numbered event it is or falls within; -1 for a pocket drop or `at T`
  /// The name as a key is written after `event`: "hit 0 5", "shot 2 cue", "7".
  std::string text() const { return camera_key_text(key, event); }
};

/// A key for a moment of shot `shot` (from 0): counting within that shot when the timeline has
/// several (`shot 2 cue`), else over the whole scene (`cue`).
CameraKey shot_key(const Timeline& timeline, int shot, CameraKeyKind kind, int a = -1, int b = -1, int ordinal = 1,
                   double seconds = 0);

/// Every moment a key can name, in the order the events list them (then the later shots' starts, the
/// contacts by balls, the drops). In a scene of several shots each counts within its shot, so it
/// stays on its moment whatever the shots before it do. Contacts later than the fifth of their kind
/// are named only when they are the `last`.
std::vector<NamedMoment> nameable_moments(const Timeline& timeline);

/// The named moment nearest `t` if one is within `snap` s, else `at T` (T rounded down to the
/// millisecond, from the start of the shot in play).
NamedMoment name_moment(const Timeline& timeline, double t, double snap);

/// The name of event `event` that resolves to its very instant: its key when it has one, else its
/// number. None for an event the timeline lacks.
std::optional<NamedMoment> name_event(const Timeline& timeline, int event);

/// `at T` in shot `shot` (counting within it in a scene of several), T in seconds from its start;
/// none when the shot ends before it.
std::optional<NamedMoment> name_at(const Timeline& timeline, int shot, double seconds);

/// The contact that first sets `ball` going in shot `shot` from another ball: `hit OTHER BALL`.
std::optional<NamedMoment> first_hit(const Timeline& timeline, int ball, int shot);

/// `ball`'s last contact in shot `shot`: `last cushion B`, `last jaw B` or `last hit OTHER B`,
/// whichever is latest (a cushion or jaw before a hit at the same instant).
std::optional<NamedMoment> last_contact(const Timeline& timeline, int ball, int shot);

/// `drop B`: `ball`'s first drop into a pocket in shot `shot`.
std::optional<NamedMoment> first_drop(const Timeline& timeline, int ball, int shot);

// --- Writing a description ----------------------------------------------------------------------------

/// A length (m) or time (s) as descriptions write them: to the millimetre (the millisecond).
double to_millimetre(double value);
Vec3 to_millimetre(const Vec3& v);

/// The part of a description after its windows, numbers as their shortest exact text (format_number)
/// and a vector's three set apart by two spaces: "hover 1 2 3  0 0 0", "look 1 2 3  5", "follow 5  -1 0 0.5".
std::string camera_mode_text(const CameraShot& shot);

/// One description line as scene text, without a comment: "event hit 0 5 0.3 0 hover 1 2 3  0 0 0".
/// It parses back to `shot` exactly (but for source locations).
std::string camera_description_text(const CameraShot& shot);

}  // namespace bsim
