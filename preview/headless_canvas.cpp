#include "headless_canvas.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "png_writer.h"

namespace bsim {

HeadlessCanvas::~HeadlessCanvas() {
  if (backend_) ImGui_ImplOpenGL3_Shutdown();
  if (imgui_) ImGui::DestroyContext(imgui_);
}

bool HeadlessCanvas::open(int width, int height, float text_px, std::string& error) {
  if (!gl_.open(width, height, error)) return false;
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.f / 30.f;
  fonts_ = add_ui_fonts(*io.Fonts, text_px);
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    error = "cannot set up text drawing on the OpenGL context";
    return false;
  }
  backend_ = true;
  return true;
}

ImDrawList* HeadlessCanvas::begin_2d() {
  ImGui::SetCurrentContext(imgui_);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  return ImGui::GetForegroundDrawList();
}

void HeadlessCanvas::end_2d() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool HeadlessCanvas::write_png(const std::string& path, std::string& error) {
  return write_gl_png(path, pixels(), width(), height(), error);
}

}  // namespace bsim
