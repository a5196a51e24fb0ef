#pragma once
// The animatic's frames drawn and handed on at once: each picture is read back straight into one of
// two buffers (from the offscreen buffer it was drawn in, with no copy into the canvas first) while a
// thread of its own hands the other buffer, the frame before, to the sink (ffmpeg's pipe), so drawing
// and encoding overlap.
#include <cstddef>
#include <cstdint>
#include <functional>

namespace bsim {

struct PreviewOptions;
struct Shot;
class HeadlessCanvas;
class SceneRenderer;
class ProgressReporter;

/// Takes one frame: width x height RGBA pixels, the bottom row first (as GL has them). False stops
/// the animatic.
using FrameSink = std::function<bool(const std::uint8_t* pixels, std::size_t bytes)>;

/// Draws frames 0 to `frames` - 1 of the shot's movie at options.fps, with the overlays `options`
/// asks for, on `canvas` (options.width x options.height) with `renderer` (set up for the shot's
/// scene), and hands each to `sink` in order on a thread of its own while the next is drawn. `progress`, when given,
/// advances as each frame is drawn. False when the sink failed or Ctrl-C came (InterruptGuard).
bool draw_animatic_frames(const PreviewOptions& options, const Shot& shot, HeadlessCanvas& canvas,
                          SceneRenderer& renderer, int frames, const FrameSink& sink, ProgressReporter* progress);

}  // namespace bsim
