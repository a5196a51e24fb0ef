#pragma once
// POV-Ray frames, the sound track, rendering and the movie, all inside a run's staging directory:
// nothing reaches the output directory until the whole run has succeeded (see output_stage.h).
#include <string>

#include "export_options.h"
#include "render_jobs.h"

namespace bsim {

struct Shot;
class OutputStage;
struct RunSummary;

/// The programs a run needs, found on PATH before any work starts.
struct RunPrograms {
  std::string povray;  ///< empty when the run renders nothing
  std::string ffmpeg;
};

/// Finds POV-Ray and ffmpeg when the run renders (neither for --no-render or --events-only); false
/// with `error` naming the missing one and the set-up command.
bool find_run_programs(const ExportOptions& options, RunPrograms& programs, std::string& error);

/// Writes frames/*.pov (and the shared include) and soundtrack.wav into the stage.
bool write_frames_and_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            std::string& error);

/// Renders the staged frames (reusing stored pictures, see frame_cache.h) and encodes the staged
/// movie.mp4, filling the summary's frame counts and times. Interrupted: Ctrl-C came, every child
/// was stopped; the caller discards the stage.
RunOutcome render_movie(const Shot& shot, const ExportOptions& options, const RunPrograms& programs,
                        const OutputStage& stage, RunSummary& summary, std::string& error);

}  // namespace bsim
