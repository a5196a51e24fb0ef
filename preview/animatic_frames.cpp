#include "animatic_frames.h"

#include <array>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include <imgui.h>

#include "child_process.h"
#include "frames.h"
#include "headless_canvas.h"
#include "overlays.h"
#include "preview_options.h"
#include "progress_reporter.h"
#include "scene_renderer.h"
#include "shot.h"

namespace bsim {

namespace {

/// Two frame buffers passed between the drawing (this thread) and a thread of their own that hands
/// them to the sink, in the order drawn: a buffer is drawn into again only once the sink has it.
class FrameHandoff {
 public:
  FrameHandoff(std::size_t bytes, const FrameSink& sink) : sink_(sink) {
    for (std::vector<std::uint8_t>& b : buffers_) b.resize(bytes);
    thread_ = std::thread([this] { hand_on(); });
  }
  ~FrameHandoff() { close(); }
  FrameHandoff(const FrameHandoff&) = delete;
  FrameHandoff& operator=(const FrameHandoff&) = delete;

  /// The buffer to draw the next frame into, once the sink is done with it; null after the sink failed.
  std::uint8_t* next() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return failed_ || !full_[drawn_]; });
    return failed_ ? nullptr : buffers_[drawn_].data();
  }
  /// Hands the buffer next() gave, drawn, to the sink.
  void submit() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      full_[drawn_] = true;
      drawn_ ^= 1;
    }
    changed_.notify_all();
  }
  /// Waits until the sink has every frame submitted; false when it failed.
  bool close() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      closing_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
    return !failed_;
  }

 private:
  void hand_on() {
    for (int slot = 0;; slot ^= 1) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return full_[slot] || closing_; });
        if (!full_[slot]) return;  // closing, every frame handed on
      }
      const bool ok = sink_(buffers_[slot].data(), buffers_[slot].size());
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        full_[slot] = false;
        failed_ = failed_ || !ok;
      }
      changed_.notify_all();
      if (!ok) return;
    }
  }

  const FrameSink& sink_;
  std::array<std::vector<std::uint8_t>, 2> buffers_;
  std::array<bool, 2> full_{false, false};
  int drawn_ = 0;  ///< the buffer the next frame is drawn into
  bool closing_ = false, failed_ = false;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::thread thread_;
};

}  // namespace

bool draw_animatic_frames(const PreviewOptions& options, const Shot& shot, HeadlessCanvas& canvas,
                          SceneRenderer& renderer, int frames, const FrameSink& sink, ProgressReporter* progress) {
  const int width = options.width, height = options.height;
  const bool overlays = options.overlays.any();
  const OverlayPaths paths = overlays ? overlay_paths(shot) : OverlayPaths{};
  FrameHandoff handoff(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, sink);
  bool ok = true;
  for (int k = 0; k < frames && ok; ++k) {
    std::uint8_t* buffer = InterruptGuard::interrupted() ? nullptr : handoff.next();
    if (!buffer) {
      ok = false;
      break;
    }
    const MovieFrame shown = shot.movie.frame(k, options.fps);  // the movie's frame: a replay's too
    const FrameState frame = scripted_frame(shot, shown);
    if (!overlays) {
      renderer.draw_offscreen(shot.scene, frame, width, height);  // read from where it is drawn
    } else {
      // The overlays go over the picture in the canvas, as a snapshot's do.
      renderer.draw(shot.scene, frame, width, height);
      ImDrawList* list = canvas.begin_2d();
      draw_overlays(
          *list,
          OverlayFrame{shot, shown.time, frame.camera, double(width), double(height), canvas.fonts(), 0, 0, &paths},
          options.overlays);
      canvas.end_2d();
    }
    renderer.read_picture(width, height, buffer);  // waits for the drawing: the picture is in `buffer`
    handoff.submit();
    if (progress) progress->advance();
  }
  return handoff.close() && ok && !InterruptGuard::interrupted();
}

}  // namespace bsim
