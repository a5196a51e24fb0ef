#pragma once
// Short words for what the pictures label: events, camera descriptions, cue phases, and their colours.
#include <string>

#include "cue_script.h"
#include "event.h"
#include "scene.h"

namespace bsim {

/// "follow ball 0", "hover", "look ball 3" (ball indices as the scene file writes them).
std::string camera_shot_label(const CameraShot& shot);
/// "ball-ball 0·5", "ball-rail 3 · rail 2", "cue → 0", "start", "end".
std::string event_label(const Event& event);
std::string cue_phase_label(CuePhase phase);

/// Colours as 0xAABBGGRR (ImGui's packing), chosen to be told apart on a dark ground.
unsigned event_color(EventType type);
unsigned pocket_color();
unsigned camera_mode_color(CameraMode mode);
unsigned cue_phase_color(CuePhase phase);
/// A ball's colour for lines and dots (dark balls lightened so they show on cloth and dark panels).
unsigned ball_ui_color(int number, int alpha = 255);

}  // namespace bsim
