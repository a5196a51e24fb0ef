#pragma once
// POV-Ray frames, the sound track, rendering and the movie, all inside a run's staging directory:
// nothing reaches the output directory until the whole run has succeeded (see output_stage.h).
#include <cstdint>
#include <string>
#include <vector>

#include "export_options.h"
#include "pov_frame.h"
#include "render_jobs.h"
#include "run_summary.h"

namespace bsim {

struct Scene;
struct Shot;
class OutputStage;

/// The programs a run needs, found on PATH before any work starts.
struct RunPrograms {
  std::string povray;  ///< empty when the run renders nothing
  std::string ffmpeg;
};

/// Finds POV-Ray and ffmpeg when the run renders (neither for --no-render or --events-only); false
/// with `error` naming the missing one and the set-up command.
bool find_run_programs(const ExportOptions& options, RunPrograms& programs, std::string& error);

/// The frames folder as written, in memory: each movie frame's content computed once (frame_content),
/// its .pov text written from it, the frame store's keys taken from the same text and the partial
/// renders planned from the same bounds.
struct StagedFrames {
  std::string include;                 ///< billiards.inc
  std::vector<FrameContent> contents;  ///< movie frame k's content, k from 0
  std::string captions;                ///< captions.txt; empty when the run writes none
  std::string lens;                    ///< lens.txt
};

/// Writes frames/*.pov (and the shared include, captions.txt, lens.txt) and soundtrack.wav into the
/// stage; `frames` gets what was written. `summary` gets the sound track's measured loudness.
bool write_frames_and_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            StagedFrames& frames, RunSummary& summary, std::string& error);

/// The frame store's key (frame_cache.h) of each of the `frames` frames written into `frames_dir`
/// (their .pov text without comments, the shared include, the size and the quality, each frame's
/// caption and lens line), read back from the files: for a folder this run did not write (a farm's).
std::vector<std::uint64_t> frame_store_keys(const std::string& frames_dir, int frames, const ExportOptions& options);
/// The same keys from the frames as written, without reading anything back.
std::vector<std::uint64_t> frame_store_keys(const StagedFrames& frames, const ExportOptions& options);

/// Traces only what changed (changed_region.h): each job whose camera is that of an earlier job (the
/// latest such) reuses that job's picture and traces its changed rectangles only, unless they would
/// cost nearly the whole frame. Sets the jobs' references and rectangles. The jobs' frames are taken
/// from `frames` (as written).
void plan_partial_frames(const Scene& scene, const StagedFrames& frames, const ExportOptions& options,
                         std::vector<FrameJob>& jobs);
/// The same, computing each job's frame_content anew.
void plan_partial_frames(const Shot& shot, const ExportOptions& options, std::vector<FrameJob>& jobs);

/// Renders the staged frames (reusing stored pictures, see frame_cache.h) and encodes the staged
/// movie.mp4, filling the summary's frame counts and times. Interrupted: Ctrl-C came, every child
/// was stopped; the caller discards the stage.
RunOutcome render_movie(const Shot& shot, const ExportOptions& options, const RunPrograms& programs,
                        const OutputStage& stage, const StagedFrames& frames, RunSummary& summary, std::string& error);

}  // namespace bsim
