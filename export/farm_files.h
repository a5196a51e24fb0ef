#pragma once
// The files of a farm run (`--farm slurm`, farm_slurm.h), in DIR/farm/: farm.conf (the run's settings
// and the job ids), chunks.txt (one FIRST-LAST line per array task), copies.txt (`FRAME SOURCE`: a
// frame that is the same as an earlier one), the two job scripts, the program's copy and the logs;
// and the frames' pictures, as the jobs and the submission see them.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "changed_region.h"
#include "export_options.h"

namespace bsim::farm {

inline constexpr const char* kConf = "farm/farm.conf";
inline constexpr const char* kChunks = "farm/chunks.txt";
inline constexpr const char* kCopies = "farm/copies.txt";
inline constexpr const char* kPartial = "farm/partial.txt";
inline constexpr const char* kProgram = "farm/billiards-export";
inline constexpr const char* kTaskScript = "farm/task.sh";
inline constexpr const char* kMovieScript = "farm/movie.sh";
inline constexpr const char* kLogs = "farm/logs";

/// The settings a farm run's jobs read (farm/farm.conf, `key=value` lines).
struct FarmConf {
  int fps = 0, width = 0, height = 0, frames = 0;
  Quality quality = Quality::final;
  double duration = 0;
  std::string frames_job, movie_job;  ///< ids of the last submission; empty when none
};

/// farm.conf's text for `c`.
std::string conf_text(const FarmConf& c);

/// Reads DIR/farm/farm.conf. False with `error` set when DIR holds no farm run or the file is not one.
bool read_conf(const std::string& dir, FarmConf& c, std::string& error);

/// Whether frame `frame` of the run in `dir` has its picture (a PNG that is not empty).
bool picture_there(const std::string& dir, int frame);

/// Hard-links `from` to `to` (one shared file system), copying when a link cannot be made.
bool link_or_copy(const std::string& from, const std::string& to);

/// Frames whose .pov text is an earlier frame's (balls at rest under a still camera): the same
/// picture, rendered once and copied (farm/copies.txt, `FRAME SOURCE` lines).
struct FrameCopies {
  std::map<int, int> source;               ///< copy -> the frame it copies
  std::map<int, std::vector<int>> copies;  ///< rendered frame -> its copies
  bool is_copy(int frame) const { return source.count(frame) > 0; }
  void add(int frame, int from) {
    source[frame] = from;
    copies[from].push_back(frame);
  }
};

/// Reads DIR/farm/copies.txt (none when it is missing).
FrameCopies read_copies(const std::string& dir);

/// copies.txt's text for `c`.
std::string copies_text(const FrameCopies& c);

/// Copies frame `from`'s picture to each of its copies that has none yet; false when one cannot be.
bool copy_picture(const std::string& frames_dir, const FrameCopies& c, int from);

/// Frames with no picture, a copy counting as there when the frame it copies is.
std::vector<int> missing_frames(const std::string& dir, int frames, const FrameCopies& c);

/// A frame of a chunk traced only where it changed: the earlier frame of its chunk it is laid over
/// and the rectangles traced (farm/partial.txt, `FRAME REFERENCE X0 Y0 X1 Y1 ...` lines).
struct PartialPlan {
  int reference = -1;
  std::vector<PixelRect> rects;
};

/// Reads DIR/farm/partial.txt (none when it is missing: every frame is traced whole).
std::map<int, PartialPlan> read_partial(const std::string& dir);

/// partial.txt's text for `plans`.
std::string partial_text(const std::map<int, PartialPlan>& plans);

/// chunks.txt's text: one FIRST-LAST line per array task.
std::string chunks_text(const std::vector<std::pair<int, int>>& chunks);

/// The script of a task of the frame array (farm/task.sh) for the run in `dir` (absolute).
std::string task_script(const std::string& dir);

/// The script of the movie job (farm/movie.sh) for the run in `dir` (absolute).
std::string movie_script(const std::string& dir);

/// The log of the array task that rendered (or failed) `frame`, a frame of its own (not a copy), as a
/// path inside DIR.
std::string task_log(const std::string& dir, const FarmConf& conf, int frame);

/// "frame 7 (frames/frame_00007.png)".
std::string shown_picture(int frame);

}  // namespace bsim::farm
