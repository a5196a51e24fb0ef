#pragma once
// A camera script that does not fit its shot, laid against the shot's real events as the user wrote
// it: each description at the time of the event it names (when the shot has that event), the faulty
// ones carrying their error, so the timeline picture can show why an event number is wrong.
#include <string_view>
#include <vector>

#include "diagnostics.h"
#include "timeline_picture.h"

namespace bsim {

/// One span per listed description, in file order. A description whose event exists starts at that
/// event and runs to the next later listed event (or the end); one whose event does not exist is not
/// placed and its problem says how many events there are. A placed description's `problem` holds the
/// errors located on its tokens.
std::vector<TimelineCameraSpan> written_camera_spans(const Scene& scene, const Timeline& timeline,
                                                     const std::vector<Diagnostic>& diagnostics);

/// The timeline picture's contents for a shot whose camera script failed (a Shot without scripts):
/// the events and drops as simulated, the script as written, and every error as `path:line:col:
/// error: message` (naming the file `path`).
TimelineData unscripted_timeline_data(const Shot& shot, const std::vector<Diagnostic>& diagnostics,
                                      std::string_view path);

}  // namespace bsim
