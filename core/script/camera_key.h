#pragma once
// Where a camera description's event number or key falls in the simulated shot: the instant it
// names, or why the shot never reaches it.
#include <optional>
#include <string>

#include "camera_key_text.h"
#include "scene.h"
#include "source_loc.h"
#include "timeline.h"

namespace bsim {

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

/// Resolves the event number or key `shot` starts at against the simulated shot.
KeyResolution resolve_camera_key(const CameraShot& shot, const Scene& scene, const Timeline& timeline);

/// How a message names what the description starts at: "event 5" or the key ("hit 0 5").
std::string describe_camera_key(const CameraShot& shot);

/// Where a message about a camera description points: its token when it has one, else its line.
SourceLoc message_loc(const SourceLoc& token, const SourceLoc& line);

/// "7 events (0 to 6)", "1 ball (index 0)": how many there are and their indices, for messages.
std::string counted(int count, const std::string& noun);

}  // namespace bsim
