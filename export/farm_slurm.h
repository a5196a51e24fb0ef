#pragma once
// Rendering on a Slurm cluster (`--farm`, see README "Rendering on a Slurm cluster"): the run's
// inputs go into the output directory on a shared file system, a job array renders the frames in
// contiguous chunks, and a job that waits for the whole array checks every frame and encodes the
// movie with the same ffmpeg command line as a local run, so the movie is byte for byte the same.
//
// Frames whose .pov text is the same (balls at rest under a still camera) are rendered once: only
// the first of them goes into a chunk, and its task copies its picture to the others (the movie job
// too, for any a task left).
//
// DIR/farm/ holds what the jobs need besides povray and ffmpeg on PATH: farm.conf (the settings and
// the job ids), chunks.txt (one FIRST-LAST line per array task), copies.txt (`FRAME SOURCE`: a frame
// that is the same as an earlier one), task.sh and movie.sh (the job scripts), a copy of
// billiards-export and the jobs' logs (logs/).
//
// The code: farm_files (those files and the frames' pictures), slurm_client (sbatch, squeue and
// scancel), farm_submit (the submission: this header's SlurmSubmission) and farm_modes (the job-side
// modes: status, render, assemble).
#include <string>
#include <vector>

#include "export_options.h"

namespace bsim {

struct Shot;
struct StagedFrames;
class OutputStage;

/// Seconds of work a task gets by default: long enough that Slurm's scheduling (seconds) and
/// POV-Ray's start-up are small beside it, short enough that a failed task costs little.
inline constexpr double kFarmTaskSeconds = 180.0;

/// POV-Ray's CPU time for one frame: a start-up plus a cost a pixel, fitted to README's render-time
/// table (640x360 and 1280x720, draft and final).
double estimated_frame_seconds(int width, int height, Quality quality);

/// The default --chunk: frames in about kFarmTaskSeconds of POV-Ray time, at least 1.
int default_farm_chunk(int width, int height, Quality quality);

/// Contiguous runs of `missing` (sorted frame numbers), each split into as few pieces of at most
/// `chunk` frames as it takes, of nearly equal sizes.
std::vector<std::pair<int, int>> farm_chunks(const std::vector<int>& missing, int chunk);

/// `--farm slurm`: submitting a run. Used by billiards-export's run in three steps around its
/// staging of the outputs, so a submission that fails leaves the output directory as it was.
class SlurmSubmission {
 public:
  /// Before any work: finds sbatch and checks that no job of an earlier submission into `dir` is
  /// still queued or running.
  bool prepare(const ExportOptions& options, const std::string& dir, std::string& error);
  /// After the inputs are staged (`frames`: the frames folder as written): keeps the frames an
  /// earlier submission finished whose inputs are unchanged, stages farm/ and asks sbatch
  /// (--test-only) whether it would take the jobs.
  bool stage(const Shot& shot, const ExportOptions& options, const OutputStage& stage, const StagedFrames& frames,
             std::string& error);
  /// After the stage is committed: submits the array and the movie job and prints their ids on
  /// standard output. Returns the exit status.
  int submit(std::string& error);

 private:
  std::string sbatch_, squeue_, scancel_;
  std::string dir_;   ///< absolute
  std::string name_;  ///< of the jobs
  std::vector<std::pair<int, int>> chunks_;
  int frames_ = 0, missing_ = 0, copies_ = 0, chunk_ = 0;
  std::vector<std::string> user_options_;
};

/// `billiards-export DIR --farm status|render|assemble`. Returns the exit status.
int run_farm_command(const ExportOptions& options);

}  // namespace bsim
