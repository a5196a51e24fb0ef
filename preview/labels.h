#pragma once
// Short words for what the pictures label: events, camera descriptions, cue phases, and their colours.
#include <string>
#include <vector>

#include "cue_script.h"
#include "event.h"
#include "scene.h"

namespace bsim {

/// Every ball's painted number, by file-order index (what `painted` means below).
std::vector<int> painted_numbers(const Scene& scene);
/// A ball's file-order index with its painted number beside it when the two differ: "11 (12)", "3".
/// Without `painted` (or for an index it lacks), the index alone.
std::string ball_index_text(int index, const std::vector<int>& painted);

/// "follow ball 0", "hover", "look ball 3 (12)" (ball indices as the scene file writes them, painted
/// numbers beside them where they differ).
std::string camera_shot_label(const CameraShot& shot, const std::vector<int>& painted = {});
/// "ball 0 – ball 5 (8)", "ball 3 – rail 2", "cue → ball 0", "balls 0, 1, 2 (group)", "start", "end".
std::string event_label(const Event& event, const std::vector<int>& painted = {});
/// A camera key (camera_key_text()'s form) written again with painted numbers beside its ball indices:
/// "hit 0 5 (8)", "drop 11 (12)"; text that is no key stays as it is.
std::string camera_key_label(const std::string& key, const std::vector<int>& painted);
std::string cue_phase_label(CuePhase phase);

/// Colours as 0xAABBGGRR (ImGui's packing), chosen to be told apart on a dark ground.
inline constexpr unsigned kLabelText = 0xFFECE8E6;  ///< text: IM_COL32(230, 232, 236, 255)
inline constexpr unsigned kLabelDim = 0xFFA89C96;   ///< dimmed text: IM_COL32(150, 156, 168, 255)
unsigned event_color(EventType type);
unsigned pocket_color();
unsigned camera_mode_color(CameraMode mode);
unsigned cue_phase_color(CuePhase phase);
/// A ball's colour for lines and dots (dark balls lightened so they show on cloth and dark panels).
unsigned ball_ui_color(int number, int alpha = 255);

}  // namespace bsim
