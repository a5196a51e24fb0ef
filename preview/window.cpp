// The interactive window: GLFW + the shared renderer + Dear ImGui panels (see viewer_ui.h), and the
// keys that write the free camera into the scene file (camera_edit.h). Under a test it scrubs through
// the shot by itself (--quit-after), plays typed keys (BSIM_WINDOW_INPUT, below) and saves its last
// frame (--screenshot).
#include <GLFW/glfw3.h>
#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "camera_edit.h"
#include "commands.h"
#include "fonts.h"
#include "gl_api.h"
#include "png_writer.h"
#include "scene_renderer.h"
#include "viewer_state.h"
#include "viewer_ui.h"

namespace bsim {

namespace {

constexpr double kReloadPoll = 0.25;  // s between looks at the scene file's time stamp

std::string g_glfw_error;
void remember_glfw_error(int, const char* description) { g_glfw_error = description ? description : ""; }

void (*glfw_proc(const char* name))() { return glfwGetProcAddress(name); }

bool has_display() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

// Marks every loaded library as never to be unloaded. glfwTerminate closes libGL and with it the GL
// driver; their lifetime allocations would then show in a leak checker's report without names, so
// its suppressions (gl_api.cpp) could not match them.
void keep_libraries_loaded() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name) dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}

struct GlfwSession {
  GLFWwindow* window = nullptr;
  bool imgui_glfw = false, imgui_gl = false;
  ~GlfwSession() {
    if (imgui_gl) ImGui_ImplOpenGL3_Shutdown();
    if (imgui_glfw) ImGui_ImplGlfw_Shutdown();
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
    if (window) glfwDestroyWindow(window);
    keep_libraries_loaded();
    glfwTerminate();
  }
};

// The ball under the mouse cursor, seen from the free camera, at the current time.
std::optional<int> ball_under_cursor(const ViewerState& state, const ViewRect& view) {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (!state.shot || mouse.x < view.x || mouse.y < view.y || mouse.x >= view.x + view.width ||
      mouse.y >= view.y + view.height)
    return std::nullopt;
  return ball_at_pixel(state.shot->timeline, state.time, state.orbit.view(), view.width, view.height, mouse.x - view.x,
                       mouse.y - view.y);
}

// K, L and U: the camera written into the scene file from the free camera, and undone.
// Returns true when the file changed.
bool handle_camera_keys(ViewerState& state, const ViewRect& view) {
  const ImGuiIO& io = ImGui::GetIO();
  CameraPlacement placement;
  placement.eye = state.orbit.view().eye;
  placement.look_at = state.orbit.view().target;
  bool changed = false;
  if (ImGui::IsKeyPressed(GLFW_KEY_K, false)) changed = write_camera_key(state, placement);
  if (ImGui::IsKeyPressed(GLFW_KEY_L, false)) {
    const std::optional<int> ball = state.free_camera ? ball_under_cursor(state, view) : std::nullopt;
    if (state.free_camera && !ball) {
      state.notice = "no ball under the mouse cursor: point at the ball to look at or follow, then press L";
      state.notice_is_error = true;
    } else {
      placement.kind = CameraPlacement::Kind::ball;
      placement.ball = ball.value_or(-1);
      changed = write_camera_key(state, placement);
    }
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_U, false) || (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z, false)))
    changed = undo_camera_key(state);
  if (!state.notice.empty() && (changed || state.notice_is_error))
    std::cerr << "billiards-preview: " << state.notice << "\n";
  return changed;
}

// The key bindings (listed in the window's help line and README). Returns true when the scene file
// was changed by a camera key.
bool handle_keys(ViewerState& state, GLFWwindow* window, const ViewRect& view) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return false;
  const bool shift = io.KeyShift;
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) {
    if (state.movie_time() >= state.movie_duration()) state.set_time(0);
    state.playing = !state.playing;
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) shift ? state.step_event(1) : state.step_frames(1);
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) shift ? state.step_event(-1) : state.step_frames(-1);
  if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_DOWN) || ImGui::IsKeyPressed(GLFW_KEY_PERIOD)) state.step_event(1);
  if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_UP) || ImGui::IsKeyPressed(GLFW_KEY_COMMA)) state.step_event(-1);
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET)) state.step_shot(1);
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT_BRACKET)) state.step_shot(-1);
  if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) state.set_time(0);
  if (ImGui::IsKeyPressed(GLFW_KEY_END, false)) state.set_movie_time(state.movie_duration());
  if (ImGui::IsKeyPressed(GLFW_KEY_C, false)) state.free_camera = !state.free_camera;
  if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) state.overlays.paths = !state.overlays.paths;
  if (ImGui::IsKeyPressed(GLFW_KEY_E, false)) state.overlays.events = !state.overlays.events;
  if (ImGui::IsKeyPressed(GLFW_KEY_M, false)) state.overlays.camera = !state.overlays.camera;
  if (ImGui::IsKeyPressed(GLFW_KEY_N, false)) state.overlays.table = !state.overlays.table;
  if (ImGui::IsKeyPressed(GLFW_KEY_A, false)) state.antialias = !state.antialias;
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) load_into(state);
  if (ImGui::IsKeyPressed(GLFW_KEY_Q, false) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false))
    glfwSetWindowShouldClose(window, GLFW_TRUE);
  return handle_camera_keys(state, view);
}

// A test hook, not an option: BSIM_WINDOW_INPUT="C K shift+Right mouse:320,180 L U" plays key
// presses into the window as if typed, one every other frame (pressed, then released), and closes
// the window after the last. `mouse:X,Y` puts the cursor at X,Y (window units) from then on.
// Keys: a letter, `.`, `,`, `[`, `]`, Right, Left, Home, End, Space, each optionally after `shift+`.
class InputScript {
 public:
  explicit InputScript(const char* text) {
    if (!text) return;
    active_ = true;
    std::istringstream in(text);
    for (std::string word; in >> word;) {
      Step step;
      if (word.rfind("mouse:", 0) == 0) {
        float x = 0, y = 0;
        if (std::sscanf(word.c_str() + 6, "%f,%f", &x, &y) == 2) step.cursor = ImVec2(x, y);
      } else {
        if (word.rfind("shift+", 0) == 0) {
          step.shift = true;
          word.erase(0, 6);
        }
        step.key = key_code(word);
      }
      if (step.key < 0 && !step.cursor)
        std::cerr << "billiards-preview: BSIM_WINDOW_INPUT: no key " << word << "\n";
      else
        steps_.push_back(step);
    }
  }

  bool active() const { return active_; }
  const ImVec2* cursor() const { return cursor_ ? &*cursor_ : nullptr; }

  /// Feeds the next press or release before a frame. Returns true once every step has been played.
  bool feed(GLFWwindow* window) {
    if (!active_) return false;
    if (held_key_ >= 0) {
      ImGui_ImplGlfw_KeyCallback(window, held_key_, 0, GLFW_RELEASE, 0);
      if (held_shift_) ImGui_ImplGlfw_KeyCallback(window, GLFW_KEY_LEFT_SHIFT, 0, GLFW_RELEASE, 0);
      held_key_ = -1;
      return false;
    }
    if (next_ >= steps_.size()) return true;
    const Step& step = steps_[next_++];
    if (step.cursor) cursor_ = step.cursor;
    if (step.key < 0) return false;
    if (step.shift) ImGui_ImplGlfw_KeyCallback(window, GLFW_KEY_LEFT_SHIFT, 0, GLFW_PRESS, GLFW_MOD_SHIFT);
    ImGui_ImplGlfw_KeyCallback(window, step.key, 0, GLFW_PRESS, step.shift ? GLFW_MOD_SHIFT : 0);
    held_key_ = step.key;
    held_shift_ = step.shift;
    return false;
  }

 private:
  struct Step {
    int key = -1;
    bool shift = false;
    std::optional<ImVec2> cursor;
  };

  static int key_code(const std::string& name) {
    if (name.size() == 1 && name[0] >= 'A' && name[0] <= 'Z') return GLFW_KEY_A + (name[0] - 'A');
    static const std::pair<const char*, int> kNames[] = {
        {".", GLFW_KEY_PERIOD},        {",", GLFW_KEY_COMMA},     {"[", GLFW_KEY_LEFT_BRACKET},
        {"]", GLFW_KEY_RIGHT_BRACKET}, {"Right", GLFW_KEY_RIGHT}, {"Left", GLFW_KEY_LEFT},
        {"Home", GLFW_KEY_HOME},       {"End", GLFW_KEY_END},     {"Space", GLFW_KEY_SPACE}};
    for (const auto& [n, code] : kNames)
      if (name == n) return code;
    return -1;
  }

  bool active_ = false;
  std::vector<Step> steps_;
  std::size_t next_ = 0;
  int held_key_ = -1;  ///< the key pressed on the last frame, released on this one
  bool held_shift_ = false;
  std::optional<ImVec2> cursor_;
};

// Mouse on the 3D view drives the free camera: left drag orbits, right (or middle) drag pans, the wheel zooms.
void handle_mouse(ViewerState& state, const ViewRect& view) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!state.free_camera || io.WantCaptureMouse) return;
  const bool inside = io.MousePos.x >= view.x && io.MousePos.x < view.x + view.width && io.MousePos.y >= view.y &&
                      io.MousePos.y < view.y + view.height;
  if (inside && io.MouseWheel != 0) state.orbit.zoom(io.MouseWheel);
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) state.orbit.orbit(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
    state.orbit.pan(io.MouseDelta.x, io.MouseDelta.y, view.height);
}

bool save_screenshot(const std::string& path, int width, int height) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  std::string error;
  if (!write_gl_png(path, pixels, width, height, error)) {
    std::cerr << "billiards-preview: error: " << error << "\n";
    return false;
  }
  return true;
}

// The default picture size for the primary monitor's work area (the screen less task bars).
PictureSize fitting_picture() {
  int x = 0, y = 0, width = 0, height = 0;
#if GLFW_VERSION_MAJOR > 3 || (GLFW_VERSION_MAJOR == 3 && GLFW_VERSION_MINOR >= 3)
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) glfwGetMonitorWorkarea(monitor, &x, &y, &width, &height);
#endif
  return default_window_picture(width, height);
}

// Opens the window with a GL 3.3 core context and loads the GL functions. Returns 0, or the exit
// status when that fails (2: no display at all).
int open_window(GlfwSession& session, const PreviewOptions& options, const std::string& shown_path) {
  glfwSetErrorCallback(remember_glfw_error);
  if (!glfwInit()) {
    std::cerr << "billiards-preview: no display for the window (" << g_glfw_error << ")\n";
    return 2;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
  const std::string title = "billiards-preview \xE2\x80\x94 " + shown_path;
  // The window is the picture plus room for the controls below it; without --size it fits the screen.
  const PictureSize picture = options.size_given ? PictureSize{options.width, options.height} : fitting_picture();
  session.window = glfwCreateWindow(picture.width, picture.height + kControlsHeight, title.c_str(), nullptr, nullptr);
  if (!session.window) {
    std::cerr << "billiards-preview: error: cannot open an OpenGL 3.3 window (" << g_glfw_error << ")\n";
    return 1;
  }
  glfwMakeContextCurrent(session.window);
  glfwSwapInterval(options.quit_after > 0 ? 0 : 1);
  const char* missing = nullptr;
  if (!load_gl_table(glfw_proc, &missing)) {
    std::cerr << "billiards-preview: error: the window's OpenGL lacks " << missing << "\n";
    return 1;
  }
  return 0;
}

// Dear ImGui on the window; session.imgui_glfw and session.imgui_gl say whether it started.
UiFonts start_imgui(GlfwSession& session) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  const UiFonts fonts = add_ui_fonts(*io.Fonts, 16.f);
  ImGui::StyleColorsDark();
  session.imgui_glfw = ImGui_ImplGlfw_InitForOpenGL(session.window, true);
  session.imgui_gl = ImGui_ImplOpenGL3_Init("#version 330 core");
  return fonts;
}

// (Re)loads the scene file into the viewer and the renderer, printing what the load said.
void load_scene(ViewerState& state, SceneRenderer& renderer) {
  if (load_into(state)) renderer.set_scene(state.shot->scene);
  for (const std::string& line : state.messages) std::cerr << line << "\n";
}

// Moves the time on by `delta` seconds while playing. Returns true when a test's scrub is over.
bool advance_time(ViewerState& state, const PreviewOptions& options, double since_start, float delta) {
  // A test drives the window by itself: it scrubs from start to end over --quit-after seconds.
  if (options.quit_after > 0) {
    const double progress = std::min(since_start / options.quit_after, 1.0);
    state.set_movie_time(progress * state.movie_duration());
    return progress >= 1.0;
  }
  if (state.playing) {
    // On through the movie: past the game's end into its replay, at the replay's half speed.
    state.set_movie_time(state.movie_time() + delta * state.speed);
    if (state.movie_time() >= state.movie_duration()) state.playing = false;
  }
  return false;
}

// The shot in the view's part of the window, then the overlays over it.
void draw_view(ViewerState& state, SceneRenderer& renderer, const ViewRect& view, int fb_width, int fb_height,
               const UiFonts& fonts) {
  const ImGuiIO& io = ImGui::GetIO();
  // ImGui works in window units, GL in framebuffer pixels; they differ on high-density screens.
  const double sx = fb_width / std::max(1.0, double(io.DisplaySize.x));
  const double sy = fb_height / std::max(1.0, double(io.DisplaySize.y));
  FrameState frame = scripted_frame(*state.shot, state.shown());
  if (state.free_camera) frame.camera = state.orbit.view();
  renderer.set_multisampling(state.antialias ? 4 : 0);
  const int w = static_cast<int>(view.width * sx), h = static_cast<int>(view.height * sy);
  renderer.draw(state.shot->scene, frame, w, h, static_cast<int>(view.x * sx),
                fb_height - static_cast<int>((view.y + view.height) * sy));
  draw_view_overlays(state, frame.camera, view, fonts);
}

struct FramebufferSize {
  int width = 0, height = 0;  ///< px
};

// One frame into the back buffer: input, the cleared window, the shot, the controls.
// `file_changed` is set when a camera key changed the scene file; `cursor`, when set, is where the
// mouse is taken to be (a test's input script).
FramebufferSize draw_window_frame(ViewerState& state, SceneRenderer& renderer, GLFWwindow* window,
                                  const PreviewOptions& options, const UiFonts& fonts, const ImVec2* cursor,
                                  bool& file_changed) {
  ImGuiIO& io = ImGui::GetIO();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (cursor) io.MousePos = *cursor;
  ImGui::NewFrame();
  int fb_width = 0, fb_height = 0;
  glfwGetFramebufferSize(window, &fb_width, &fb_height);
  const ViewRect view = view_rect(io.DisplaySize.x, io.DisplaySize.y, options.width, options.height);
  file_changed = handle_keys(state, window, view);
  handle_mouse(state, view);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_width, fb_height);
  glClearColor(0.07f, 0.075f, 0.085f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  if (state.shot && view.width >= 1 && view.height >= 1) draw_view(state, renderer, view, fb_width, fb_height, fonts);
  draw_controls(state, fonts, io.DisplaySize.x, io.DisplaySize.y);
  ImGui::Render();
  glViewport(0, 0, fb_width, fb_height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return {fb_width, fb_height};
}

}  // namespace

int run_window(const PreviewOptions& options, const SceneSource& source) {
  if (!has_display()) {
    std::cerr << "billiards-preview: no display for the window (DISPLAY is not set); "
                 "use --at SECONDS -o FILE.png, --timeline -o FILE.png or --movie FILE.mp4\n";
    return 2;
  }
  GlfwSession session;
  if (const int failed = open_window(session, options, source.shown_path)) return failed;
  const UiFonts fonts = start_imgui(session);
  SceneRenderer renderer;
  std::string error;
  if (!session.imgui_glfw || !session.imgui_gl || !renderer.init(error)) {
    std::cerr << "billiards-preview: error: " << (error.empty() ? "cannot set up the window's drawing" : error) << "\n";
    return 1;
  }

  ViewerState state;
  state.source = source;
  state.fps = options.fps;
  state.overlays = options.overlays;
  state.overlays.aim = true;  // the aim of a `pot` cue is shown in the window unless switched off
  load_scene(state, renderer);
  FileWatch watch(source.path);
  InputScript input(std::getenv("BSIM_WINDOW_INPUT"));

  const double started = glfwGetTime();
  double last_poll = started;
  bool quit = false;
  while (!quit) {
    glfwPollEvents();
    const double now = glfwGetTime();
    if (now - last_poll >= kReloadPoll) {
      last_poll = now;
      if (watch.changed()) load_scene(state, renderer);
    }
    quit = advance_time(state, options, now - started, ImGui::GetIO().DeltaTime) || input.feed(session.window);
    bool file_changed = false;
    const FramebufferSize fb =
        draw_window_frame(state, renderer, session.window, options, fonts, input.cursor(), file_changed);
    if (file_changed) {
      // Reloaded at once, so the scripted camera shows the change (or the window shows the errors).
      load_scene(state, renderer);
      watch.changed();
    }
    if (glfwWindowShouldClose(session.window)) quit = true;
    if (quit && options.screenshot && !save_screenshot(*options.screenshot, fb.width, fb.height)) return 1;
    glfwSwapBuffers(session.window);
  }
  return state.shot ? 0 : 1;
}

}  // namespace bsim
