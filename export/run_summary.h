#pragma once
// run.json: what one run of billiards-export did, for a person or a CI job reading its output
// directory later: the scene and options, how many frames were rendered and how many reused, where
// the time went, which POV-Ray and ffmpeg made the pictures and the movie, and every file written.
#include <chrono>
#include <optional>
#include <string>

#include "export_options.h"

namespace bsim {

/// `text` as a JSON string: quoted, with quotes, backslashes and control characters escaped (the
/// run summary and events.json).
std::string json_string(const std::string& text);

/// File name of the summary inside the output directory.
inline constexpr const char* kRunSummaryName = "run.json";

struct RunSummary {
  std::string scene;   ///< the scene's path as given, or "<built-in break.scn>"
  std::string output;  ///< the output directory as given
  int frames_total = 0;
  int frames_rendered = 0;  ///< by POV-Ray in this run
  int frames_reused = 0;    ///< copied from the frame store or from an identical frame of this run
  int frames_partial = 0;   ///< of those rendered, traced only where they changed (changed_region.h)
  double traced_share = 1;  ///< of the pixels of the frames rendered, the share POV-Ray traced
  double simulating = 0;    ///< s: reading the scene, simulating, scripting the camera and stick
  double writing = 0;       ///< s: the data files, the frames' .pov files and the sound track
  double rendering = 0;     ///< s inside POV-Ray (wall time)
  double encoding = 0;      ///< s inside ffmpeg (wall time)
  /// The sound track as written, measured (ITU-R BS.1770-4): integrated loudness in LUFS (none for a
  /// track too quiet to gate) and true peak in dBTP.
  std::optional<double> loudness_lufs;
  double true_peak_dbtp = 0;
  std::string povray_version;  ///< first line of `povray --version`; empty when not rendering
  std::string ffmpeg_version;  ///< first line of `ffmpeg -version`
};

/// Seconds of wall time since `start`: how run.json's times are taken.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The first line `program flag` prints that starts with `prefix` ("POV-Ray", "ffmpeg version"),
/// without a copyright notice; empty if it prints none.
std::string program_version(const std::string& program, const std::string& flag, const std::string& prefix);

/// Writes the summary; `staged_dir` is listed for the files (each top-level file with its size, the
/// frames folder as a count and a total), run.json itself excepted.
bool write_run_summary(const RunSummary& summary, const ExportOptions& options, const std::string& staged_dir,
                       std::string& error);

}  // namespace bsim
