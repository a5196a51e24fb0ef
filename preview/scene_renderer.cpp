#include "scene_renderer.h"

#include <Eigen/Geometry>

#include "ball_model.h"
#include "gl_api.h"
#include "shaders.h"
#include "shot.h"
#include "table_model.h"

namespace bsim {

/// A linked shader program and where its uniforms are (a type of its own, not in the unnamed namespace,
/// as SceneRenderer::Impl holds it).
struct SceneProgram {
  GLuint id = 0;
  GLint model = -1, normal_matrix = -1, view_projection = -1, color = -1, number = -1, striped = -1, alpha = -1,
        eye = -1, numbers = -1;
};

namespace {

constexpr int kNumberCell = 128;  // px per digit cell: sharp even in close-ups
constexpr float kShadowAlpha = 0.6f;

Eigen::Matrix3f to_matrix3(const Eigen::Matrix4f& m) { return m.block<3, 3>(0, 0); }

}  // namespace

FrameState scripted_frame(const Shot& shot, double t) {
  FrameState frame;
  frame.balls = shot.timeline.states(t);
  if (shot.cue) frame.cue = shot.cue->pose(t);
  frame.camera = scripted_view(shot, t);
  return frame;
}

FrameState scripted_frame(const Shot& shot, const MovieFrame& shown) {
  FrameState frame = scripted_frame(shot, shown.time);
  if (shown.replay && shot.replay_camera) {
    const CameraPose pose = shot.replay_camera->pose(shown.time);
    frame.camera.eye = pose.location;
    frame.camera.target = pose.look_at;
  }
  return frame;
}

struct SceneRenderer::Impl {
  SceneProgram programs[kMaterialCount];
  SceneProgram* current = nullptr;
  GpuMesh cloth, tops, body, pockets, bed_holes, top_holes, sphere, cue, shadow;
  GLuint numbers = 0;
  // Multisampled target, resized on demand.
  GLuint fbo = 0, color_rb = 0, depth_rb = 0;
  int fbo_width = 0, fbo_height = 0, samples = 0;
  int wanted_samples = 0, built_for = -1;
  bool kept_offscreen = false;  ///< the last picture was left in `fbo`

  ~Impl() {
    release_target();
    if (numbers) glDeleteTextures(1, &numbers);
    for (SceneProgram& p : programs)
      if (p.id) glDeleteProgram(p.id);
  }

  void release_target() {
    if (fbo) glDeleteFramebuffers(1, &fbo);
    if (color_rb) glDeleteRenderbuffers(1, &color_rb);
    if (depth_rb) glDeleteRenderbuffers(1, &depth_rb);
    fbo = color_rb = depth_rb = 0;
  }

  void ensure_target(int width, int height) {
    if (width == fbo_width && height == fbo_height && built_for == wanted_samples) return;
    release_target();
    built_for = wanted_samples;
    fbo_width = width;
    fbo_height = height;
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples = std::min(wanted_samples, static_cast<int>(max_samples));
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, color_rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb);
    glGenRenderbuffers(1, &depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
    // Without a usable offscreen buffer, draw straight into the default framebuffer (no antialiasing).
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) release_target();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  void set_model(const Eigen::Matrix4f& model) {
    glUniformMatrix4fv(current->model, 1, GL_FALSE, model.data());
    const Eigen::Matrix3f normal = to_matrix3(model).inverse().transpose();
    glUniformMatrix3fv(current->normal_matrix, 1, GL_FALSE, normal.data());
  }

  void use(Material m) {
    current = &programs[static_cast<int>(m)];
    glUseProgram(current->id);
  }

  // The steps of SceneRenderer::draw.
  void begin_frame(int width, int height, int x, int y);
  void set_camera(const ViewCamera& camera, double aspect);
  void draw_table();
  void mark_pocket_holes();
  void draw_balls(const Scene& scene, const std::vector<BallState>& balls);
  void draw_cue(const CuePose& pose);
  void draw_shadows(const std::vector<BallState>& balls, double radius);
  void finish_frame(int width, int height, int x, int y, bool resolve);
  void draw(const Scene& scene, const FrameState& frame, int width, int height, int x, int y, bool resolve);
};

SceneRenderer::SceneRenderer() : impl_(std::make_unique<Impl>()) {}
SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::init(std::string& error) {
  Impl& r = *impl_;
  for (int m = 0; m < kMaterialCount; ++m) {
    SceneProgram& p = r.programs[m];
    p.id = build_scene_program(static_cast<Material>(m), error);
    if (!p.id) return false;
    const auto loc = [&](const char* name) { return glGetUniformLocation(p.id, name); };
    p.model = loc("u_model");
    p.normal_matrix = loc("u_normal_matrix");
    p.view_projection = loc("u_view_projection");
    p.color = loc("u_color");
    p.number = loc("u_number");
    p.striped = loc("u_striped");
    p.alpha = loc("u_alpha");
    p.eye = loc("u_eye");
    p.numbers = loc("u_numbers");
  }
  r.sphere.upload(make_sphere_mesh(48, 32));
  r.cue.upload(make_cue_mesh());
  r.shadow.upload(make_shadow_quad());

  const std::vector<std::uint8_t> atlas = make_number_atlas(kNumberCell);
  glGenTextures(1, &r.numbers);
  glBindTexture(GL_TEXTURE_2D, r.numbers);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kNumberCell * 4, kNumberCell * 4, 0, GL_RED, GL_UNSIGNED_BYTE, atlas.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return true;
}

void SceneRenderer::set_multisampling(int samples) { impl_->wanted_samples = samples; }

void SceneRenderer::set_scene(const Scene& scene) {
  const TableModel table = build_table_model(scene);
  impl_->cloth.upload(table.cloth);
  impl_->tops.upload(table.tops);
  impl_->body.upload(table.body);
  impl_->pockets.upload(table.pockets);
  impl_->bed_holes.upload(table.bed_holes);
  impl_->top_holes.upload(table.top_holes);
}

// Binds the target (the multisampled buffer, or the window's part of framebuffer 0), sets the state
// every frame starts from and clears.
void SceneRenderer::Impl::begin_frame(int width, int height, int x, int y) {
  ensure_target(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glDisable(GL_SCISSOR_TEST);
  if (fbo) {
    glViewport(0, 0, width, height);
  } else {
    glViewport(x, y, width, height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, width, height);
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilMask(0xFF);
  glClearColor(0.018f, 0.016f, 0.02f, 1.f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// Gives every program the camera, and binds the number atlas they sample.
void SceneRenderer::Impl::set_camera(const ViewCamera& camera, double aspect) {
  const Eigen::Matrix4f view_projection = projection_matrix(camera, aspect) * view_matrix(camera);
  for (const SceneProgram& p : programs) {
    glUseProgram(p.id);
    glUniformMatrix4fv(p.view_projection, 1, GL_FALSE, view_projection.data());
    glUniform3f(p.eye, float(camera.eye.x()), float(camera.eye.y()), float(camera.eye.z()));
    glUniform1i(p.numbers, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, numbers);
}

void SceneRenderer::Impl::draw_table() {
  mark_pocket_holes();
  use(Material::table);
  set_model(Eigen::Matrix4f::Identity());
  glStencilFunc(GL_EQUAL, 0, 1);
  cloth.draw();
  glStencilFunc(GL_EQUAL, 0, 2);
  tops.draw();
  glDisable(GL_STENCIL_TEST);
  body.draw();
  pockets.draw();
}

// Pocket holes are cut with the stencil: the circles mark bit 1 (on the bed plane) and bit 2 (on the
// top plane) wherever they project, and each plane is drawn only outside its own circles. That is
// exact for a plane, and the pockets' insides then show through. Leaves the stencil test on.
void SceneRenderer::Impl::mark_pocket_holes() {
  use(Material::flat);
  set_model(Eigen::Matrix4f::Identity());
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glStencilMask(1);
  glStencilFunc(GL_ALWAYS, 1, 1);
  bed_holes.draw();
  glStencilMask(2);
  glStencilFunc(GL_ALWAYS, 2, 2);
  top_holes.draw();
  glStencilMask(0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
}

void SceneRenderer::Impl::draw_balls(const Scene& scene, const std::vector<BallState>& balls) {
  const double radius = scene.physics.ball_radius;
  use(Material::ball);
  for (std::size_t i = 0; i < balls.size() && i < scene.balls.size(); ++i) {
    // A pocketed ball is drawn where the timeline leaves it, in its pocket's cup (pocket_fall.h), as
    // the POV-Ray frames draw it.
    const BallState& s = balls[i];
    const int number = scene.balls[i].number;
    Eigen::Affine3d model = Eigen::Translation3d(s.position) * s.orientation.normalized() * Eigen::Scaling(radius);
    set_model(model.matrix().cast<float>());
    const Vec3 color = ball_color(number);
    glUniform3f(current->color, float(color.x()), float(color.y()), float(color.z()));
    glUniform1i(current->number, number);
    glUniform1i(current->striped, ball_striped(number) ? 1 : 0);
    sphere.draw();
  }
}

void SceneRenderer::Impl::draw_cue(const CuePose& pose) {
  const bool drawable = pose.visible && pose.axis.norm() > 1e-9;
  if (!drawable) return;
  const Quat turn = Quat::FromTwoVectors(Vec3::UnitX(), pose.axis.normalized());
  const Eigen::Affine3d model = Eigen::Translation3d(pose.tip) * turn;
  use(Material::cue);
  set_model(model.matrix().cast<float>());
  cue.draw();
}

// Contact shadows: soft dark discs laid over the cloth.
void SceneRenderer::Impl::draw_shadows(const std::vector<BallState>& balls, double radius) {
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.f, -4.f);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  use(Material::shadow);
  for (const BallState& s : balls) {
    if (s.motion == Motion::pocketed || s.position.z() < 0.5 * radius) continue;
    // A ball in the air (or sinking) casts a fainter, wider shadow.
    const double lift = std::clamp((s.position.z() - radius) / (4 * radius), -1.0, 1.0);
    const double size = radius * (1.45 + 0.6 * std::abs(lift));
    const Eigen::Affine3d model =
        Eigen::Translation3d(Vec3(s.position.x(), s.position.y(), 0)) * Eigen::Scaling(size, size, 1.0);
    set_model(model.matrix().cast<float>());
    glUniform1f(current->alpha, float(kShadowAlpha * (1.0 - 0.6 * std::abs(lift))));
    shadow.draw();
  }
  glDisable(GL_BLEND);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
}

// Leaves the GL state as the other drawing expects it and, when drawn offscreen, resolves the picture
// into framebuffer 0 at (x, y), unless it is to stay offscreen (`resolve` false, read_picture()).
void SceneRenderer::Impl::finish_frame(int width, int height, int x, int y, bool resolve) {
  glStencilMask(0xFF);
  glDisable(GL_SCISSOR_TEST);
  glUseProgram(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  if (fbo && resolve) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  if (fbo) glBindFramebuffer(GL_FRAMEBUFFER, 0);
  kept_offscreen = fbo && !resolve;
}

void SceneRenderer::Impl::draw(const Scene& scene, const FrameState& frame, int width, int height, int x, int y,
                               bool resolve) {
  begin_frame(width, height, x, y);
  set_camera(frame.camera, static_cast<double>(width) / std::max(height, 1));
  draw_table();
  draw_balls(scene, frame.balls);
  draw_cue(frame.cue);
  draw_shadows(frame.balls, scene.physics.ball_radius);
  finish_frame(width, height, x, y, resolve);
}

void SceneRenderer::draw(const Scene& scene, const FrameState& frame, int width, int height, int x, int y) {
  impl_->draw(scene, frame, width, height, x, y, true);
}

void SceneRenderer::draw_offscreen(const Scene& scene, const FrameState& frame, int width, int height) {
  impl_->draw(scene, frame, width, height, 0, 0, false);
}

void SceneRenderer::read_picture(int width, int height, std::uint8_t* rgba) const {
  const Impl& r = *impl_;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, r.kept_offscreen ? r.fbo : 0);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);  // rows of 4-byte pixels: no padding
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace bsim
