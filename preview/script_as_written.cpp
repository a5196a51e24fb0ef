#include "script_as_written.h"

#include <algorithm>

#include "camera_moment.h"
#include "labels.h"
#include "shot.h"

namespace bsim {

namespace {

bool same_place(const SourceLoc& a, const SourceLoc& b) {
  return a.known() && a.line == b.line && a.column == b.column;
}

// The errors the validation located on this description's keyword, event number or key, or ball index.
std::string problems_of(const CameraShot& shot, const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity != Severity::error) continue;
    if (!same_place(d.loc, shot.loc) && !same_place(d.loc, shot.event_loc) && !same_place(d.loc, shot.ball_loc) &&
        !same_place(d.loc, shot.key.a_loc) && !same_place(d.loc, shot.key.b_loc))
      continue;
    if (!text.empty()) text += "; ";
    text += d.message;
  }
  return text;
}

}  // namespace

std::vector<TimelineCameraSpan> written_camera_spans(const Scene& scene, const Timeline& timeline,
                                                     const std::vector<Diagnostic>& diagnostics) {
  const int count = static_cast<int>(timeline.events().size());
  std::vector<TimelineCameraSpan> spans;
  for (const CameraShot& shot : scene.camera) {
    TimelineCameraSpan span;
    span.event = shot.event;
    if (shot.key.kind != CameraKeyKind::event) span.key = camera_key_text(shot.key);
    span.mode = shot.mode;
    span.label = camera_shot_label(shot, painted_numbers(scene));
    const KeyResolution at = resolve_camera_key(shot, scene, timeline);
    span.placed = at.instant.has_value();
    // Unplaced, it sits beside the others with nothing to compare: say what the shot has instead.
    if (span.placed)
      span.problem = problems_of(shot, diagnostics);
    else if (shot.key.kind == CameraKeyKind::event)
      span.problem = "no such event \xE2\x80\x94 the shot has " + std::to_string(count) +
                     (count > 0 ? " (0 to " + std::to_string(count - 1) + ")" : "");
    else
      span.problem = at.problem;
    span.begin = span.end = span.placed ? at.instant->time : timeline.duration();
    spans.push_back(span);
  }
  // Each placed description holds until the next later one, whatever order the file lists them in:
  // an out-of-order description then shows where its event really falls.
  for (TimelineCameraSpan& span : spans) {
    if (!span.placed) continue;
    span.end = timeline.duration();
    for (const TimelineCameraSpan& other : spans)
      if (other.placed && other.begin > span.begin) span.end = std::min(span.end, other.begin);
  }
  return spans;
}

TimelineData unscripted_timeline_data(const Shot& shot, const std::vector<Diagnostic>& diagnostics,
                                      std::string_view path) {
  TimelineData data = timeline_data(shot);
  data.camera = written_camera_spans(shot.scene, shot.timeline, diagnostics);
  data.windows.clear();
  data.cue.clear();
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::error) data.script_errors.push_back(format_diagnostic(d, path));
  // The picture must say the script failed even if the reason carries no error of its own.
  if (data.script_errors.empty())
    data.script_errors.push_back(std::string(path) + ": error: the camera script does not fit the shot");
  return data;
}

}  // namespace bsim
