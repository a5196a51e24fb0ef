#include "ffmpeg_assemble.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "atomic_file.h"
#include "child_process.h"
#include "frames.h"
#include "progress_reporter.h"
#include "scene_file.h"

namespace bsim {

namespace {

constexpr const char* kTempMovie = ".movie.tmp.mp4";
constexpr const char* kLog = ".ffmpeg.log";
constexpr const char* kProgress = ".ffmpeg.progress";
/// How often ffmpeg's progress is read while it encodes (it writes every half second).
constexpr std::chrono::milliseconds kProgressPoll{250};

std::string duration_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", seconds);
  return text;
}

}  // namespace

std::vector<std::string> ffmpeg_arguments(const MovieSettings& settings, const std::string& output,
                                          const std::string& progress) {
  return {settings.ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate",
          std::to_string(settings.fps), "-start_number", "0", "-i", "frames/frame_%05d.png", "-i", "soundtrack.wav",
          "-map", "0:v:0", "-map", "1:a:0",
          // The frames fill the shot exactly (core/frames.h); the cut guards the streams' common end.
          "-t", duration_text(settings.duration),
          // yuv420p needs even sizes: pad an odd one by a pixel rather than fail
          "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "medium",
          // The sensor's grain (develop.h) kept: x264's film-grain tuning (weaker deblocking and adaptive
          // quantisation, psychovisual trellis) at a quality that keeps all of it (at 18 it keeps 70 %).
          "-tune", "grain", "-crf", kMovieCrf, "-pix_fmt", "yuv420p", "-c:a", "aac", "-b:a", "192k", "-movflags",
          "+faststart", "-progress", progress, "-f", "mp4", output};
}

int encoded_frames(const std::string& progress_text) {
  for (auto at = progress_text.rfind("frame="); at != std::string::npos; at = progress_text.rfind("frame=", at - 1)) {
    if (at == 0 || progress_text[at - 1] == '\n') return std::max(0, std::atoi(progress_text.c_str() + at + 6));
  }
  return 0;
}

RunOutcome assemble_movie(const std::string& dir, const MovieSettings& settings, std::string& error) {
  const std::string temp = dir + "/" + kTempMovie, log = dir + "/" + kLog, progress_file = dir + "/" + kProgress;
  auto cleanup = [&] {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    std::filesystem::remove(log, ignored);
    std::filesystem::remove(progress_file, ignored);
  };
  cleanup();  // a progress file left by a killed run must not be read as this one's
  const pid_t pid = start_process(ffmpeg_arguments(settings, kTempMovie, kProgress), dir, log, error);
  if (pid < 0) return RunOutcome::failed;
  const int total = frame_count(settings.duration, settings.fps);  // the frames the movie holds
  ProgressReporter progress("billiards-export", "encoding", total, 0, progress_style(settings.quiet));
  bool success = false;
  pid_t done = -1;
  while (done != pid) {
    done = wait_any(success, kProgressPoll);
    if (done == 0) {
      progress.set_done(encoded_frames(read_text_file(progress_file)));
      continue;
    }
    if (done < 0) {
      stop_process(pid);
      cleanup();
      return RunOutcome::interrupted;
    }
  }
  if (!success) {
    error = "ffmpeg could not make movie.mp4: " + error_from_log(read_text_file(log));
    cleanup();
    return RunOutcome::failed;
  }
  progress.set_done(total);
  progress.finish();
  const bool placed = move_into_place(temp, dir + "/movie.mp4", error);
  cleanup();
  return placed ? RunOutcome::done : RunOutcome::failed;
}

}  // namespace bsim
