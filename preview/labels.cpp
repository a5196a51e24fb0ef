#include "labels.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <imgui.h>

#include "ball_model.h"
#include "camera_key_text.h"

namespace bsim {

std::vector<int> painted_numbers(const Scene& scene) {
  std::vector<int> numbers;
  for (const Ball& b : scene.balls) numbers.push_back(b.number);
  return numbers;
}

std::string ball_index_text(int index, const std::vector<int>& painted) {
  std::string text = std::to_string(index);
  if (index >= 0 && static_cast<std::size_t>(index) < painted.size() &&
      painted[static_cast<std::size_t>(index)] != index)
    text += " (" + std::to_string(painted[static_cast<std::size_t>(index)]) + ")";
  return text;
}

std::string camera_shot_label(const CameraShot& shot, const std::vector<int>& painted) {
  switch (shot.mode) {
    case CameraMode::hover: return "hover";
    case CameraMode::look: return "look ball " + ball_index_text(shot.ball, painted);
    case CameraMode::follow: return "follow ball " + ball_index_text(shot.ball, painted);
  }
  return "?";
}

std::string camera_key_label(const std::string& key, const std::vector<int>& painted) {
  int event = 0;
  const std::optional<CameraKey> parsed = parse_camera_key(key, &event);
  if (!parsed) return key;
  return camera_key_text(*parsed, event, [&](int ball) { return ball_index_text(ball, painted); });
}

std::string event_label(const Event& event, const std::vector<int>& painted) {
  const auto ball = [&](std::size_t k) {
    return k < event.balls.size() ? ball_index_text(event.balls[k], painted) : "?";
  };
  switch (event.type) {
    case EventType::start: return "start";
    case EventType::end: return "end";
    case EventType::cue: return "cue \xE2\x86\x92 ball " + ball(0);
    case EventType::ball_ball: {
      if (event.balls.size() <= 2) return "ball " + ball(0) + " \xE2\x80\x93 ball " + ball(1);
      // A group collision: "balls 0, 1, 2 (group)".
      std::string out = "balls " + ball(0);
      for (std::size_t k = 1; k < event.balls.size(); ++k) out += ", " + ball(k);
      return out + " (group)";
    }
    case EventType::ball_rail: return "ball " + ball(0) + " \xE2\x80\x93 rail " + std::to_string(event.rail);
    case EventType::ball_jaw: return "ball " + ball(0) + " \xE2\x80\x93 jaw of pocket " + std::to_string(event.pocket);
  }
  return "?";
}

std::string cue_phase_label(CuePhase phase) {
  switch (phase) {
    case CuePhase::approach: return "approach";
    case CuePhase::preflight: return "practice strokes";
    case CuePhase::impact: return "strike";
    case CuePhase::retraction: return "retraction";
  }
  return "?";
}

unsigned event_color(EventType type) {
  switch (type) {
    case EventType::start:
    case EventType::end: return IM_COL32(170, 170, 176, 255);
    case EventType::cue: return IM_COL32(255, 236, 120, 255);
    case EventType::ball_ball: return IM_COL32(255, 142, 54, 255);
    case EventType::ball_rail: return IM_COL32(84, 188, 255, 255);
    case EventType::ball_jaw: return IM_COL32(120, 230, 150, 255);
  }
  return IM_COL32_WHITE;
}

unsigned pocket_color() { return IM_COL32(236, 92, 210, 255); }

unsigned camera_mode_color(CameraMode mode) {
  switch (mode) {
    case CameraMode::hover: return IM_COL32(128, 108, 220, 255);
    case CameraMode::look: return IM_COL32(196, 160, 52, 255);
    case CameraMode::follow: return IM_COL32(62, 168, 104, 255);
  }
  return IM_COL32_WHITE;
}

unsigned cue_phase_color(CuePhase phase) {
  switch (phase) {
    case CuePhase::approach: return IM_COL32(150, 112, 70, 255);
    case CuePhase::preflight: return IM_COL32(196, 150, 92, 255);
    case CuePhase::impact: return IM_COL32(232, 84, 64, 255);
    case CuePhase::retraction: return IM_COL32(120, 100, 84, 255);
  }
  return IM_COL32_WHITE;
}

unsigned ball_ui_color(int number, int alpha) {
  const Vec3 linear = ball_color(number);
  double c[3];
  for (int i = 0; i < 3; ++i) {
    const double v = linear[i];
    c[i] = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
  }
  const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  if (luma < 0.3) {
    const double lift = 0.3 - luma + 0.15;
    for (double& v : c) v = v + (1 - v) * lift;
  }
  const auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  return IM_COL32(byte(c[0]), byte(c[1]), byte(c[2]), alpha);
}

}  // namespace bsim
