#include "viewer_ui.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ball_look.h"
#include "game_panel.h"
#include "labels.h"
#include "overlays.h"
#include "shot.h"
#include "stroke_diagram.h"
#include "timeline_picture.h"

namespace bsim {

namespace {

constexpr float kEventListWidth = 300;  // px
constexpr double kSpeeds[] = {0.1, 0.25, 0.5, 1.0, 2.0};
constexpr const char* kKeyHelp =
    "Space play/pause   \xE2\x86\x90 \xE2\x86\x92 frame   Shift+\xE2\x86\x90 \xE2\x86\x92 or , . event   [ ] shot   "
    "Home End   "
    "C scripted/free camera   K write the free camera into the scene   L look at/follow the ball under the cursor   "
    "U undo   P paths   E events   M camera map   A antialias   R reload   Q quit";

// A scene of several shots: which one is in play, and a step to the previous or next shot's strike.
void shot_buttons(ViewerState& state) {
  ImGui::SameLine(0, 16);
  if (ImGui::Button("[ shot")) state.step_shot(-1);
  ImGui::SameLine();
  ImGui::Text("shot %d of %d", state.shot_in_play() + 1, state.shot_count());
  ImGui::SameLine();
  if (ImGui::Button("shot ]")) state.step_shot(1);
}

void transport(ViewerState& state) {
  if (ImGui::Button("|<")) state.set_time(0);
  ImGui::SameLine();
  if (ImGui::Button("<< event")) state.step_event(-1);
  ImGui::SameLine();
  if (ImGui::Button("< frame")) state.step_frames(-1);
  ImGui::SameLine();
  if (ImGui::Button(state.playing ? "  pause  " : "  play  ")) {
    if (!state.playing && state.movie_time() >= state.movie_duration()) state.set_time(0);
    state.playing = !state.playing;
  }
  ImGui::SameLine();
  if (ImGui::Button("frame >")) state.step_frames(1);
  ImGui::SameLine();
  if (ImGui::Button("event >>")) state.step_event(1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) state.set_movie_time(state.movie_duration());
  if (state.shot_count() > 1) shot_buttons(state);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  char speed[16];
  std::snprintf(speed, sizeof speed, "%gx", state.speed);
  if (ImGui::BeginCombo("speed", speed)) {
    for (double s : kSpeeds) {
      std::snprintf(speed, sizeof speed, "%gx", s);
      if (ImGui::Selectable(speed, s == state.speed)) state.speed = s;
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::Text("t = %.3f s / %.3f s   frame %d%s", state.time, state.duration(),
              static_cast<int>(std::lround(state.movie_time() * state.fps)), state.replay ? "   replay" : "");
}

void switches(ViewerState& state) {
  if (ImGui::RadioButton("scripted camera", !state.free_camera)) state.free_camera = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("free orbit camera", state.free_camera)) state.free_camera = true;
  ImGui::SameLine(0, 30);
  ImGui::Checkbox("paths", &state.overlays.paths);
  ImGui::SameLine();
  ImGui::Checkbox("events", &state.overlays.events);
  ImGui::SameLine();
  ImGui::Checkbox("camera map", &state.overlays.camera);
  ImGui::SameLine();
  ImGui::Checkbox("numbers", &state.overlays.table);
  ImGui::SameLine();
  ImGui::Checkbox("aim", &state.overlays.aim);
  ImGui::SameLine(0, 30);
  ImGui::Checkbox("antialias", &state.antialias);
}

// The compact timeline as a slider: click or drag anywhere on it to set the time.
void scrub_bar(ViewerState& state, const UiFonts& fonts) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  const float height = compact_timeline_height(fonts);
  ImGui::InvisibleButton("scrub", ImVec2(width, height));
  // The bar runs over the movie's time: past the game's end, its replay.
  TimelineLayout layout{at.x, at.y, width, height, true, state.movie_time()};
  const TimelineAxis axis = draw_timeline(*ImGui::GetWindowDrawList(), state.timeline, fonts, layout);
  if (ImGui::IsItemActive() && state.shot) {
    state.set_movie_time(axis.time_at(ImGui::GetIO().MousePos.x));
    state.playing = false;
  }
}

void event_list(ViewerState& state, float window_height) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kEventListWidth, std::max(120.f, window_height - kControlsHeight - 16)),
                           ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Events (click to jump)") && state.shot) {
    const Event* current = nullptr;
    for (const Event& e : state.shot->timeline.events())
      if (e.time <= state.time + 1e-9) current = &e;
    int listed_shot = state.shot_count() > 1 ? -1 : 0;
    for (const Event& e : state.shot->timeline.events()) {
      if (e.shot != listed_shot) {  // a scene of several shots: each shot's events under its name
        listed_shot = e.shot;
        ImGui::TextDisabled("shot %d", e.shot + 1);
      }
      char label[160];
      std::snprintf(label, sizeof label, "%3d  %7.3f s  %s", e.index, e.time,
                    event_label(e, state.timeline.painted).c_str());
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(event_color(e.type)));
      if (ImGui::Selectable(label, &e == current)) {
        state.set_time(e.time);
        state.playing = false;
      }
      ImGui::PopStyleColor();
    }
    for (const PocketDrop& d : state.shot->timeline.pocket_drops()) {
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pocket_color()), "     %7.3f s  drop %s: into %s", d.time,
                         ball_index_text(d.ball, state.timeline.painted).c_str(),
                         pocket_name(state.shot->scene.pockets, d.pocket).c_str());
    }
  }
  ImGui::End();
}

void problems(const ViewerState& state, float window_width) {
  if (state.messages.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(window_width / 2, 8), ImGuiCond_Always, ImVec2(0.5f, 0));
  ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0), ImVec2(window_width - 40, 400));
  ImGui::SetNextWindowBgAlpha(0.9f);
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
  ImGui::Begin(state.load_failed ? "The scene has errors" : "Warnings", nullptr, flags);
  for (const std::string& line : state.messages) {
    const bool is_error = line.find(": error:") != std::string::npos;
    ImGui::TextColored(is_error ? ImVec4(1.f, 0.45f, 0.4f, 1.f) : ImVec4(1.f, 0.85f, 0.4f, 1.f), "%s", line.c_str());
  }
  if (state.load_failed)
    ImGui::TextUnformatted(state.shot ? "Showing the last version that loaded; fix the file and save to reload."
                                      : "Fix the file and save: it reloads by itself.");
  ImGui::End();
}

// The scene's stroke as a small ball diagram (speed, where the tip meets the ball, elevation), in a
// panel at the bottom left of the picture; none without a stroke.
void stroke_panel(const ViewerState& state, const UiFonts& fonts, float window_height) {
  if (!state.shot) return;
  const std::vector<Cue>& cues = state.shot->scene.cues;
  const auto k = static_cast<std::size_t>(state.shot_in_play());
  if (k >= cues.size() || !cues[k].stroke) return;
  const Stroke& stroke = *cues[k].stroke;
  const ImVec2 size = stroke_diagram_size(fonts);
  ImGui::SetNextWindowPos(ImVec2(8, window_height - kControlsHeight - 8), ImGuiCond_FirstUseEver, ImVec2(0, 1));
  ImGui::SetNextWindowBgAlpha(0.8f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse;
  // The title names the shot when there are several; "###" keeps the panel the same window across shots.
  const std::string title =
      (state.shot_count() > 1 ? "Stroke of shot " + std::to_string(k + 1) : std::string("Stroke")) + "###stroke";
  if (ImGui::Begin(title.c_str(), nullptr, flags)) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::Dummy(size);
    draw_stroke_diagram(*ImGui::GetWindowDrawList(), stroke, fonts, at);
  }
  ImGui::End();
}

// The balls left, as small discs in their colours (a stripe's band on white) with their numbers.
void ball_discs(const std::vector<int>& balls, const UiFonts& fonts) {
  const float r = std::round(fonts.small_size * 0.75f), step = 2 * r + 3;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(step * static_cast<float>(balls.size()), 2 * r));
  ImDrawList& list = *ImGui::GetWindowDrawList();
  const SrgbColor w = kBallIvory;
  const ImU32 ivory = IM_COL32(w.r, w.g, w.b, 255);
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const ImVec2 centre(at.x + r + step * static_cast<float>(k), at.y + r);
    const SrgbColor c = ball_srgb(balls[k]);
    const ImU32 colour = IM_COL32(c.r, c.g, c.b, 255);
    list.AddCircleFilled(centre, r, ball_striped(balls[k]) ? ivory : colour);
    if (ball_striped(balls[k])) {
      list.PushClipRect(ImVec2(centre.x - r, centre.y - r * 0.55f), ImVec2(centre.x + r, centre.y + r * 0.55f), true);
      list.AddCircleFilled(centre, r, colour);
      list.PopClipRect();
    }
    list.AddCircle(centre, r, IM_COL32(255, 255, 255, 90));  // the 8 shows on a dark panel
    list.AddCircleFilled(centre, r * 0.55f, ivory);
    const std::string number = std::to_string(balls[k]);
    const float px = r * 0.95f;
    const ImVec2 size = fonts.small->CalcTextSizeA(px, FLT_MAX, 0, number.c_str());
    list.AddText(fonts.small, px, ImVec2(centre.x - size.x / 2, centre.y - size.y / 2), IM_COL32(20, 20, 20, 255),
                 number.c_str());
  }
}

}  // namespace

void draw_game_panel(const Shot& shot, double t, const UiFonts& fonts, float window_width) {
  if (!shot.game) return;
  const GamePanel panel = game_panel(shot, t);
  ImGui::SetNextWindowPos(ImVec2(window_width - 8, 8), ImGuiCond_FirstUseEver, ImVec2(1, 0));
  ImGui::SetNextWindowBgAlpha(0.8f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse;
  if (ImGui::Begin("Game###game", nullptr, flags)) {
    for (const GamePanelLine& line : panel.lines) {
      const ImVec4 colour = ImGui::ColorConvertU32ToFloat4(game_tone_color(line.tone));
      if (!line.balls) {
        ImGui::TextColored(colour, "%s", line.text.c_str());
        continue;
      }
      ImGui::TextColored(colour, "%s", line.text.substr(0, line.text.find(':') + 1).c_str());
      ImGui::SameLine();
      ball_discs(panel.on_table, fonts);
    }
  }
  ImGui::End();
}

PictureSize default_window_picture(int area_width, int area_height) {
  constexpr int kLargest = 720, kSmallest = 180, kFallback = 432;  // picture heights, px
  auto at_height = [](int height) { return PictureSize{(height * 16 + 8) / 9, height}; };
  if (area_width <= 0 || area_height <= 0) return at_height(kFallback);
  const int by_height = area_height - kDecorationsHeight - kControlsHeight;
  const int by_width = (area_width - kDecorationsWidth) * 9 / 16;
  return at_height(std::clamp(std::min(by_height, by_width), kSmallest, kLargest));
}

ViewRect view_rect(float window_width, float window_height, int picture_width, int picture_height) {
  const float area_h = std::max(0.f, window_height - kControlsHeight);
  const float aspect = static_cast<float>(picture_width) / static_cast<float>(std::max(picture_height, 1));
  ViewRect r;
  r.width = std::min(window_width, area_h * aspect);
  r.height = r.width / aspect;
  r.x = std::floor((window_width - r.width) / 2);
  r.y = std::floor((area_h - r.height) / 2);
  r.width = std::floor(r.width);
  r.height = std::floor(r.height);
  return r;
}

void draw_view_overlays(const ViewerState& state, const ViewCamera& camera, const ViewRect& view,
                        const UiFonts& fonts) {
  if (!state.shot) return;
  ImDrawList& list = *ImGui::GetBackgroundDrawList();
  const OverlayFrame frame{*state.shot, state.time, camera, view.width,  view.height,
                           fonts,       view.x,     view.y, &state.paths};
  list.PushClipRect(ImVec2(view.x, view.y), ImVec2(view.x + view.width, view.y + view.height), true);
  if (state.free_camera) draw_scripted_frustum(list, frame, static_cast<double>(view.width) / view.height);
  draw_overlays(list, frame, state.overlays);
  // With several shots, which one is in play ("shot 2 of 3 · scripted camera").
  const std::string shot_text = state.shot_count() > 1 ? "shot " + std::to_string(state.shot_in_play() + 1) + " of " +
                                                             std::to_string(state.shot_count()) + "  \xC2\xB7  "
                                                       : std::string();
  const std::string which_text =
      shot_text +
      (state.free_camera ? "free orbit camera (drag: orbit, right-drag: pan, wheel: zoom)" : "scripted camera");
  const char* which = which_text.c_str();
  list.AddText(fonts.small, fonts.small_size,
               ImVec2(view.x + view.width - fonts.small->CalcTextSizeA(fonts.small_size, 1e9f, 0, which).x - 8,
                      view.y + view.height - fonts.small_size - 6),
               IM_COL32(220, 220, 220, 200), which);
  if (!state.notice.empty()) {
    // What the last camera key did, at the bottom left of the picture above the status line.
    const float wrap = view.width - 16;
    const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small_size, 1e9f, wrap, state.notice.c_str());
    const float top = view.y + view.height - size.y - 2 * fonts.small_size - 20;
    list.AddRectFilled(ImVec2(view.x + 4, top - 3), ImVec2(view.x + 12 + size.x, top + size.y + 3),
                       IM_COL32(0, 0, 0, 170), 3.f);
    list.AddText(fonts.small, fonts.small_size, ImVec2(view.x + 8, top),
                 state.notice_is_error ? IM_COL32(255, 130, 120, 255) : IM_COL32(170, 240, 170, 255),
                 state.notice.c_str(), nullptr, wrap);
  }
  list.PopClipRect();
}

void draw_controls(ViewerState& state, const UiFonts& fonts, float window_width, float window_height) {
  const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoSavedSettings;
  ImGui::SetNextWindowPos(ImVec2(0, window_height - kControlsHeight));
  ImGui::SetNextWindowSize(ImVec2(window_width, kControlsHeight));
  ImGui::Begin("controls", nullptr, fixed);
  transport(state);
  scrub_bar(state, fonts);
  switches(state);
  ImGui::PushFont(fonts.small);
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("%s", kKeyHelp);
  ImGui::PopTextWrapPos();
  ImGui::PopFont();
  ImGui::End();
  event_list(state, window_height);
  stroke_panel(state, fonts, window_height);
  if (state.shot) draw_game_panel(*state.shot, state.time, fonts, window_width);
  problems(state, window_width);
}

}  // namespace bsim
