#pragma once
// The movie: the rendered frames and the sound track into movie.mp4 (H.264 yuv420p, AAC,
// moov atom first), written under a temporary name and renamed when complete.
#include <string>
#include <vector>

#include "render_jobs.h"

namespace bsim {

/// x264's constant rate factor for the movie: low enough to keep every frame's grain (develop.h).
inline constexpr const char* kMovieCrf = "16";

struct MovieSettings {
  std::string ffmpeg;  ///< full path of the program
  int fps = 30;
  double duration = 0;  ///< s, the shot's: the movie is cut to it
  bool quiet = false;   ///< no progress lines
};

/// ffmpeg's command line, run inside the output directory, writing `output` and its progress
/// (`-progress`, key=value lines) to `progress`.
std::vector<std::string> ffmpeg_arguments(const MovieSettings& settings, const std::string& output,
                                          const std::string& progress);

/// The frames ffmpeg has encoded so far, from what it wrote with `-progress` (its last `frame=N`).
int encoded_frames(const std::string& progress_text);

/// Encodes dir/frames/frame_%05d.png and dir/soundtrack.wav into dir/movie.mp4.
RunOutcome assemble_movie(const std::string& dir, const MovieSettings& settings, std::string& error);

}  // namespace bsim
