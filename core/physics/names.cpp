#include <cstdio>

#include "ball_state.h"
#include "event.h"

namespace bsim {

std::string_view to_string(Motion motion) {
  switch (motion) {
    case Motion::stationary: return "stationary";
    case Motion::sliding: return "sliding";
    case Motion::rolling: return "rolling";
    case Motion::spinning: return "spinning";
    case Motion::falling: return "falling";
    case Motion::pocketed: return "pocketed";
  }
  return "?";
}

std::string_view to_string(EventType type) {
  switch (type) {
    case EventType::start: return "start";
    case EventType::cue: return "cue";
    case EventType::ball_ball: return "ball-ball";
    case EventType::ball_rail: return "ball-rail";
    case EventType::ball_jaw: return "ball-jaw";
    case EventType::end: return "end";
  }
  return "?";
}

std::string plan_text(const Vec3& p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.3f, %.3f)", p.x(), p.y());
  return text;
}

}  // namespace bsim
