#pragma once
// The four things billiards-preview does; each returns the process exit status.
#include <optional>
#include <string>

#include "preview_options.h"
#include "shot_source.h"
#include "timeline_picture.h"

namespace bsim {

class Timeline;

/// The time a TimeSpec names in this shot, or nullopt with `error` set (event number out of range).
std::optional<double> resolve_time(const TimeSpec& at, const Timeline& timeline, std::string& error);

/// Body text size for a picture `height` pixels high: readable at 720 lines, still legible when small.
float picture_text_px(int height);

/// --at T -o FILE.png, or several --at into a directory or a pattern: the scene is set up once and
/// each time drawn in turn.
int run_snapshot(const PreviewOptions& options, const Shot& shot);
/// --timeline -o FILE.png, of a loaded shot (timeline_data) or of one whose camera script failed
/// (unscripted_timeline_data).
int run_timeline_picture(const PreviewOptions& options, const TimelineData& data);
/// --movie FILE.mp4
int run_animatic(const PreviewOptions& options, const Shot& shot);
/// No output option: the window. Loads (and reloads) the scene itself so errors show in the window.
int run_window(const PreviewOptions& options, const SceneSource& source);

}  // namespace bsim
