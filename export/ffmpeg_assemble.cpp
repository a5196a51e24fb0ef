#include "ffmpeg_assemble.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "child_process.h"

namespace bsim {

namespace {

constexpr const char* kTempMovie = ".movie.tmp.mp4";
constexpr const char* kLog = ".ffmpeg.log";

std::string duration_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", seconds);
  return text;
}

}  // namespace

std::vector<std::string> ffmpeg_arguments(const MovieSettings& settings, const std::string& output) {
  return {settings.ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate",
          std::to_string(settings.fps), "-start_number", "0", "-i", "frames/frame_%05d.png", "-i", "soundtrack.wav",
          "-map", "0:v:0", "-map", "1:a:0",
          // The frames fill the shot exactly (core/frames.h); the cut guards the streams' common end.
          "-t", duration_text(settings.duration),
          // yuv420p needs even sizes: pad an odd one by a pixel rather than fail
          "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt",
          "yuv420p", "-c:a", "aac", "-b:a", "192k", "-movflags", "+faststart", "-f", "mp4", output};
}

RunOutcome assemble_movie(const std::string& dir, const MovieSettings& settings, std::string& error) {
  const std::string temp = dir + "/" + kTempMovie, log = dir + "/" + kLog;
  auto cleanup = [&] {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    std::filesystem::remove(log, ignored);
  };
  const pid_t pid = start_process(ffmpeg_arguments(settings, kTempMovie), dir, log, error);
  if (pid < 0) return RunOutcome::failed;
  bool success = false;
  pid_t done = -1;
  while (done != pid) {
    done = wait_any(success);
    if (done < 0) {
      stop_process(pid);
      cleanup();
      return RunOutcome::interrupted;
    }
  }
  if (!success) {
    std::ifstream in(log, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    error = "ffmpeg could not make movie.mp4: " + error_from_log(text.str());
    cleanup();
    return RunOutcome::failed;
  }
  std::error_code ec;
  std::filesystem::rename(temp, dir + "/movie.mp4", ec);
  cleanup();
  if (ec) {
    error = "cannot write " + dir + "/movie.mp4: " + ec.message();
    return RunOutcome::failed;
  }
  return RunOutcome::done;
}

}  // namespace bsim
