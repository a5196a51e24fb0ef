// --movie: every frame drawn with the GL renderer and piped raw to ffmpeg with the sound track, so a
// camera script can be judged in motion in seconds instead of the minutes POV-Ray takes.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <imgui.h>

#include "commands.h"
#include "frames.h"
#include "headless_canvas.h"
#include "overlays.h"
#include "scene_renderer.h"
#include "soundtrack.h"

extern char** environ;

namespace bsim {

namespace {

/// s; the exporter's default lead, so the animatic sounds as the movie will.
constexpr double kAnimaticAudioLead = 0.005;

/// ffmpeg reading raw RGBA frames on its standard input.
class FfmpegPipe {
 public:
  bool start(const std::vector<std::string>& args, std::string& error) {
    int fds[2];
    if (pipe(fds) != 0) {
      error = "cannot create a pipe to ffmpeg";
      return false;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int status = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[0]);
    if (status != 0) {
      close(fds[1]);
      error = "cannot run ffmpeg (install the ffmpeg package)";
      return false;
    }
    out_ = fdopen(fds[1], "wb");
    return out_ != nullptr;
  }

  bool write(const std::vector<std::uint8_t>& bytes) {
    return out_ && std::fwrite(bytes.data(), 1, bytes.size(), out_) == bytes.size();
  }

  /// Closes the pipe and waits; true when ffmpeg succeeded.
  bool finish() {
    if (out_) std::fclose(out_);
    out_ = nullptr;
    int status = 0;
    if (pid_ > 0 && waitpid(pid_, &status, 0) < 0) return false;
    pid_ = -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
  }

  ~FfmpegPipe() { finish(); }

 private:
  FILE* out_ = nullptr;
  pid_t pid_ = -1;
};

std::filesystem::path temporary_wav() {
  std::random_device device;
  return std::filesystem::temp_directory_path() / ("bsim-animatic-" + std::to_string(device()) + ".wav");
}

}  // namespace

int run_animatic(const PreviewOptions& options, const Shot& shot) {
  const int fps = options.fps, width = options.width, height = options.height;
  const int frames = frame_count(shot.timeline.duration(), fps);
  std::string error;

  // The sound lasts exactly as long as the frames, so the streams end together.
  const auto samples = static_cast<std::size_t>(frames) * kSampleRate / static_cast<std::size_t>(fps);
  AudioBuffer audio;
  const std::filesystem::path wav = temporary_wav();
  if (!mix_soundtrack(shot, {.lead = kAnimaticAudioLead, .music_path = {}}, samples, audio, error) ||
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
  const std::vector<std::string> args = {
      "ffmpeg", "-hide_banner", "-loglevel", "error", "-y",
      "-f", "rawvideo", "-pix_fmt", "rgba", "-s", std::to_string(width) + "x" + std::to_string(height),
      "-framerate", std::to_string(fps), "-i", "-", "-i", wav.string(),
      "-map", "0:v:0", "-map", "1:a:0",
      // GL rows come bottom-up; H.264 in 4:2:0 needs even sides, so an odd size gets one black line.
      "-vf", "vflip,pad=ceil(iw/2)*2:ceil(ih/2)*2",
      "-c:v", "libx264", "-preset", "ultrafast", "-crf", "20", "-pix_fmt", "yuv420p",
      "-c:a", "aac", "-b:a", "160k", "-movflags", "+faststart", "-f", "mp4", partial};
  // A dead ffmpeg must show up as a failed write, not kill the process.
  const auto previous = std::signal(SIGPIPE, SIG_IGN);
  FfmpegPipe ffmpeg;
  bool ok = ffmpeg.start(args, error);
  const bool overlays = options.overlays.paths || options.overlays.events || options.overlays.camera;
  const OverlayPaths paths = overlays ? overlay_paths(shot) : OverlayPaths{};
  for (int k = 0; ok && k < frames; ++k) {
    const double t = frame_time(k, fps);
    const FrameState frame = scripted_frame(shot, t);
    renderer.draw(shot.scene, frame, width, height);
    if (overlays) {
      ImDrawList* list = canvas.begin_2d();
      draw_overlays(*list, OverlayFrame{shot, t, frame.camera, double(width), double(height), canvas.fonts(), 0, 0, &paths},
                    options.overlays);
      canvas.end_2d();
    }
    ok = ffmpeg.write(canvas.pixels());
  }
  ok = ffmpeg.finish() && ok;
  std::signal(SIGPIPE, previous);
  std::filesystem::remove(wav);
  std::error_code ec;
  if (ok) std::filesystem::rename(partial, target, ec);
  if (!ok || ec) {
    std::filesystem::remove(partial, ec);
    std::cerr << "billiards-preview: error: " << (error.empty() ? "ffmpeg could not write " + target : error) << "\n";
    return 1;
  }
  std::cerr << "wrote " << target << " (" << frames << " frames at " << fps << " fps)\n";
  return 0;
}

}  // namespace bsim
