// --movie: every frame drawn with the GL renderer and piped raw to ffmpeg with the sound track, so a
// camera script can be judged in motion in seconds instead of the minutes POV-Ray takes. Drawing and
// encoding overlap (animatic_frames.h).

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "animatic_frames.h"
#include "atomic_file.h"
#include "child_process.h"
#include "commands.h"
#include "frames.h"
#include "headless_canvas.h"
#include "progress_reporter.h"
#include "scene_file.h"
#include "scene_renderer.h"
#include "soundtrack.h"

namespace bsim {

namespace {

/// s; the exporter's default lead, so the animatic sounds as the movie will.
constexpr double kAnimaticAudioLead = 0.005;

/// Bytes the pipe to ffmpeg holds: a good part of a frame, so that a frame goes over in a few writes
/// rather than in 64 KiB pieces, each waking ffmpeg (Linux caps it at /proc/sys/fs/pipe-max-size).
constexpr int kPipeBytes = 1 << 20;

/// ffmpeg reading raw RGBA frames on its standard input, its messages in a log file.
class FfmpegPipe {
 public:
  bool start(std::vector<std::string> args, const std::filesystem::path& log, std::string& error) {
    args.front() = find_program("ffmpeg");
    if (args.front().empty()) {
      error = "cannot run ffmpeg (install the ffmpeg package)";
      return false;
    }
    log_ = log;
    pid_ = start_process(args, ".", log_.string(), error, &fd_);
    if (pid_ < 0) return false;
    fcntl(fd_, F_SETPIPE_SZ, kPipeBytes);  // best effort: a smaller pipe only costs more writes
    return fd_ >= 0;
  }

  /// Writes one frame whole; false when ffmpeg is gone.
  bool write(const std::uint8_t* bytes, std::size_t size) {
    while (fd_ >= 0 && size > 0) {
      const ssize_t n = ::write(fd_, bytes, size);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      bytes += n;
      size -= static_cast<std::size_t>(n);
    }
    return fd_ >= 0;
  }

  /// Ctrl-C: closes the pipe, stops ffmpeg without waiting for it to finish the file and deletes
  /// its log (the process is about to die of the signal, so no destructor will).
  void stop() {
    close_pipe();
    if (pid_ >= 0) stop_process(pid_);
    pid_ = -1;
    std::error_code ec;
    if (!log_.empty()) std::filesystem::remove(log_, ec);
  }

  /// Closes the pipe and waits; true when ffmpeg succeeded, else `error` holds its last message.
  bool finish(std::string& error) {
    close_pipe();
    if (pid_ < 0) return false;
    const bool ok = wait_for(pid_);
    pid_ = -1;
    if (!ok && error.empty()) error = "ffmpeg: " + error_from_log(read_text_file(log_));
    return ok;
  }

  ~FfmpegPipe() {
    std::string ignored;
    finish(ignored);
    std::error_code ec;
    if (!log_.empty()) std::filesystem::remove(log_, ec);
  }

 private:
  void close_pipe() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  int fd_ = -1;
  pid_t pid_ = -1;
  std::filesystem::path log_;
};

std::filesystem::path temporary_file(const char* extension) {
  std::random_device device;
  return std::filesystem::temp_directory_path() / ("bsim-animatic-" + std::to_string(device()) + extension);
}

/// H.264 in 4:2:0 needs even sides: an odd --size is padded by one black line, which the user is told.
void warn_if_padded(int width, int height) {
  if (width % 2 == 0 && height % 2 == 0) return;
  std::cerr << "billiards-preview: warning: --size " << width << "x" << height
            << " has an odd side, which H.264 cannot encode: the animatic is " << width + width % 2 << "x"
            << height + height % 2 << " (a black line added at the " << (width % 2 ? "right" : "")
            << (width % 2 && height % 2 ? " and " : "") << (height % 2 ? "bottom" : "") << ")\n";
}

/// ffmpeg's command line: raw RGBA frames on its standard input and the sound track into `partial`.
std::vector<std::string> ffmpeg_arguments(const PreviewOptions& options, const std::filesystem::path& wav,
                                          const std::string& partial) {
  return {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgba", "-s",
          std::to_string(options.width) + "x" + std::to_string(options.height), "-framerate",
          std::to_string(options.fps), "-i", "-", "-i", wav.string(), "-map", "0:v:0", "-map", "1:a:0",
          // GL rows come bottom-up; H.264 in 4:2:0 needs even sides, so an odd size gets one black line.
          "-vf", "vflip,pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "ultrafast", "-crf", "20",
          "-pix_fmt", "yuv420p", "-c:a", "aac", "-b:a", "160k", "-movflags", "+faststart", "-f", "mp4", partial};
}

}  // namespace

int run_animatic(const PreviewOptions& options, const Shot& shot) {
  const int fps = options.fps, width = options.width, height = options.height;
  const int frames = shot.movie.frame_count(fps);
  std::string error;
  // Ctrl-C (or SIGTERM) from here on stops ffmpeg and deletes the half-written file before dying.
  InterruptGuard guard;

  // The sound lasts exactly as long as the frames, so the streams end together.
  const auto samples = static_cast<std::size_t>(frames) * kSampleRate / static_cast<std::size_t>(fps);
  AudioBuffer audio;
  const std::filesystem::path wav = temporary_file(".wav");
  const SoundMovie movie{&shot.movie, shot.replay_camera ? &*shot.replay_camera : nullptr};
  if (!mix_movie_soundtrack({shot.scene, shot.timeline, *shot.camera}, movie,
                            {.lead = kAnimaticAudioLead, .music_path = {}, .level = {}}, samples, audio, error) ||
      !write_wav(wav.string(), audio, error)) {
    std::cerr << "billiards-preview: error: " << error << "\n";
    return 1;
  }

  HeadlessCanvas canvas;
  SceneRenderer renderer;
  if (!canvas.open(width, height, picture_text_px(height), error) || !renderer.init(error)) {
    std::filesystem::remove(wav);
    std::cerr << "billiards-preview: error: " << error << "\n";
    return 1;
  }
  renderer.set_scene(shot.scene);

  const std::string target = *options.movie;
  const std::string partial = target + ".partial";
  warn_if_padded(width, height);
  // A dead ffmpeg must show up as a failed write, not kill the process.
  const auto previous = std::signal(SIGPIPE, SIG_IGN);
  FfmpegPipe ffmpeg;
  bool ok = ffmpeg.start(ffmpeg_arguments(options, wav, partial), temporary_file(".log"), error);
  ProgressReporter progress("billiards-preview", "animatic", frames, 0, progress_style(options.quiet));
  const FrameSink sink = [&ffmpeg](const std::uint8_t* pixels, std::size_t bytes) {
    return ffmpeg.write(pixels, bytes);
  };
  ok = ok && draw_animatic_frames(options, shot, canvas, renderer, frames, sink, &progress);
  if (InterruptGuard::interrupted())
    ffmpeg.stop();
  else
    ok = ffmpeg.finish(error) && ok;
  std::signal(SIGPIPE, previous);
  std::filesystem::remove(wav);
  if (InterruptGuard::interrupted()) {
    std::error_code ec;
    std::filesystem::remove(partial, ec);
    progress.message("billiards-preview: interrupted: nothing was written to " + target);
    guard.finish();  // dies of the signal, as the user asked
    return 130;
  }
  progress.finish();
  if (ok) ok = move_into_place(partial, target, error);
  if (!ok) {
    std::error_code ec;
    std::filesystem::remove(partial, ec);
    std::cerr << "billiards-preview: error: " << (error.empty() ? "ffmpeg could not write " + target : error) << "\n";
    return 1;
  }
  if (!options.quiet) std::cerr << "wrote " << target << " (" << frames << " frames at " << fps << " fps)\n";
  return 0;
}

}  // namespace bsim
