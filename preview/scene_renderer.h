#pragma once
// Draws one frame of the shot with OpenGL: the table, the balls (coloured, striped, numbered, turned
// by their orientation), the stick and soft contact shadows, seen from a ViewCamera. Shared by the
// headless snapshots, the animatic and the window; needs a current GL 3.3 core context.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ball_state.h"
#include "cue_script.h"
#include "frames.h"
#include "mesh.h"
#include "scene.h"
#include "view.h"

namespace bsim {

struct Shot;

/// Everything that moves, at one instant.
struct FrameState {
  std::vector<BallState> balls;  ///< file order
  CuePose cue;
  ViewCamera camera;
};

/// The shot at time t, seen from its scripted camera.
FrameState scripted_frame(const Shot& shot, double t);
/// What the movie shows at one of its frames (frames.h): the shot at the frame's time, seen from the
/// camera filming it (the replay's on a replay frame).
FrameState scripted_frame(const Shot& shot, const MovieFrame& shown);

class SceneRenderer {
 public:
  SceneRenderer();
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  bool init(std::string& error);
  /// Samples per pixel for antialiasing: 0 (none, fastest), 2 or 4. A software rasteriser pays about
  /// twice the frame time for 4, so the animatic and the window default to 0 and snapshots use 4.
  void set_multisampling(int samples);
  /// Rebuilds the table for `scene` (after a reload).
  void set_scene(const Scene& scene);
  /// Draws a width x height picture into framebuffer 0 with its lower-left corner at (x, y).
  void draw(const Scene& scene, const FrameState& frame, int width, int height, int x = 0, int y = 0);
  /// Draws as draw() does at (0, 0), but leaves the picture where it was drawn (the offscreen buffer,
  /// none copied into framebuffer 0), for read_picture().
  void draw_offscreen(const Scene& scene, const FrameState& frame, int width, int height);
  /// Reads the width x height picture last drawn into `rgba` (RGBA, bottom row first, as GL has it):
  /// straight from the offscreen buffer after draw_offscreen(); after draw(), from framebuffer 0,
  /// with what was drawn over it there (the overlays).
  void read_picture(int width, int height, std::uint8_t* rgba) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bsim
