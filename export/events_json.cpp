// events.json: the numbered events, the pocket drops and every ball's final state (format in README).
#include <cstdio>
#include <ostream>
#include <string>

#include "number_format.h"
#include "outputs.h"
#include "run_summary.h"
#include "shot.h"

namespace bsim {

namespace {

std::string list(const std::vector<int>& values) {
  std::string out = "[";
  for (std::size_t k = 0; k < values.size(); ++k) out += (k ? ", " : "") + std::to_string(values[k]);
  return out + "]";
}

/// The cue event's stick: its heading (degrees) and, with a stroke, the stroke as written.
std::string cue_json(const Cue& cue) {
  std::string out = ", \"heading\": " + format_number(cue.heading_deg);
  if (!cue.stroke) return out;
  const Stroke& s = *cue.stroke;
  return out + ", \"stroke\": {\"speed\": " + format_number(s.speed) + ", \"side\": " + format_number(s.side) +
         ", \"height\": " + format_number(s.height) + ", \"elevation\": " + format_number(s.elevation_deg) + "}";
}

/// A player's plan for a shot: the ball (painted number) and pocket meant, a safety or a push-out; empty
/// for a written shot and for a plan that names nothing (the break).
std::string planned_json(const GameRecord* game, int shot) {
  if (!game) return "";
  for (const GameTurn& turn : game->turns) {
    if (turn.shot != shot || turn.written) continue;
    const ShotCall& call = turn.planned;
    if (call.push_out) return ", \"planned\": {\"push_out\": true}";
    if (call.safety) return ", \"planned\": {\"safety\": true}";
    if (call.ball < 0) return "";
    return ", \"planned\": {\"ball\": " + std::to_string(call.ball) + ", \"pocket\": " + std::to_string(call.pocket) +
           "}";
  }
  return "";
}

std::string event_json(const Event& e, const Scene& scene, const GameRecord* game) {
  std::string out = "{\"index\": " + std::to_string(e.index) + ", \"time\": " + format_number(e.time) +
                    ", \"type\": \"" + std::string(to_string(e.type)) + "\", \"shot\": " + std::to_string(e.shot + 1);
  if (e.type == EventType::start || e.type == EventType::end) return out + "}";
  out += ", \"balls\": " + list(e.balls);
  if (e.type == EventType::ball_rail) out += ", \"rail\": " + std::to_string(e.rail);
  if (e.type == EventType::ball_jaw) out += ", \"pocket\": " + std::to_string(e.pocket);
  out += ", \"speed\": " + format_number(e.speed);
  if (e.type == EventType::cue)
    out += cue_json(scene.cues[static_cast<std::size_t>(e.shot)]) + planned_json(game, e.shot);
  if (e.grouped && !e.contacts.empty()) {
    // A group collision: every contact of the group, in the order they began.
    out += ", \"contacts\": [";
    for (std::size_t k = 0; k < e.contacts.size(); ++k) {
      const Contact& c = e.contacts[k];
      out += std::string(k ? ", " : "") + "{\"balls\": " + list({c.a, c.b}) + ", \"time\": " + format_number(c.time) +
             ", \"speed\": " + format_number(c.speed) + "}";
    }
    out += "]";
  }
  return out + "}";
}

/// One turn of the game: the rules' verdict on one shot.
std::string turn_json(const GameTurn& turn) {
  const TurnVerdict& v = turn.verdict;
  const auto flag = [](bool b) { return b ? "true" : "false"; };
  std::string out = "{\"shot\": " + std::to_string(turn.shot + 1) + ", \"player\": " + std::to_string(turn.player) +
                    ", \"break\": " + flag(v.break_shot) + ", \"legal\": " + flag(v.legal) +
                    ", \"foul\": " + (v.foul.empty() ? std::string("null") : json_string(v.foul)) +
                    ", \"pocketed\": " + list(v.pocketed) + ", \"continues\": " + flag(v.continues) +
                    ", \"ball_in_hand\": " + flag(v.in_hand != InHand::none);
  if (v.in_hand != InHand::none)
    out += std::string(", \"in_hand\": ") + (v.in_hand == InHand::kitchen ? "\"kitchen\"" : "\"anywhere\"");
  if (v.push_out) out += ", \"push_out\": true";
  return out + ", \"call\": " + json_string(v.call) + "}";
}

/// The rules' record of a played game: its rules, players, winner and one turn per shot.
std::string game_json(const GameRecord& game) {
  std::string out =
      "  \"game\": {\n    \"rules\": \"" + std::string(rack_game_name(game.rules)) + "\",\n    \"players\": [";
  for (std::size_t k = 0; k < game.players.size(); ++k) out += (k ? ", " : "") + json_string(game.players[k]);
  out += "],\n    \"winner\": " + (game.winner ? std::to_string(*game.winner) : std::string("null")) + ",\n";
  if (game.shot_limit) out += "    \"shot_limit\": true,\n";
  out += "    \"turns\": [";
  for (std::size_t k = 0; k < game.turns.size(); ++k) out += (k ? ",\n      " : "\n      ") + turn_json(game.turns[k]);
  return out + (game.turns.empty() ? "]\n  }" : "\n    ]\n  }");
}

}  // namespace

void write_events_json(const Shot& shot, std::ostream& out) {
  const Timeline& timeline = shot.timeline;
  out << "{\n  \"duration\": " << format_number(timeline.duration()) << ",\n  \"events\": [";
  const auto& events = timeline.events();
  for (std::size_t k = 0; k < events.size(); ++k)
    out << (k ? ",\n    " : "\n    ") << event_json(events[k], shot.scene, shot.game ? &*shot.game : nullptr);
  out << (events.empty() ? "],\n" : "\n  ],\n");

  out << "  \"shots\": [";
  const auto& shots = timeline.shots();
  for (std::size_t k = 0; k < shots.size(); ++k)
    out << (k ? ",\n    " : "\n    ") << "{\"shot\": " << k + 1 << ", \"cue\": " << format_number(shots[k].cue)
        << ", \"rest\": " << format_number(shots[k].rest) << "}";
  out << (shots.empty() ? "],\n" : "\n  ],\n");

  out << "  \"pocketed\": [";
  const auto& drops = timeline.pocket_drops();
  for (std::size_t k = 0; k < drops.size(); ++k)
    out << (k ? ",\n    " : "\n    ") << "{\"time\": " << format_number(drops[k].time)
        << ", \"ball\": " << drops[k].ball << ", \"pocket\": " << drops[k].pocket << "}";
  out << (drops.empty() ? "],\n" : "\n  ],\n");

  out << "  \"final\": [";
  for (int i = 0; i < timeline.ball_count(); ++i) {
    const BallState s = timeline.state(i, timeline.duration());
    const bool pocketed = s.motion == Motion::pocketed || s.motion == Motion::falling;
    out << (i ? ",\n    " : "\n    ") << "{\"ball\": " << i << ", \"number\": " << shot.scene.ball(i).number
        << ", \"position\": [" << format_number(s.position.x()) << ", " << format_number(s.position.y()) << ", "
        << format_number(s.position.z()) << "], \"pocketed\": " << (pocketed ? "true" : "false") << "}";
  }
  out << (timeline.ball_count() == 0 ? "]" : "\n  ]");
  if (shot.game) out << ",\n" << game_json(*shot.game);
  out << "\n}\n";
}

}  // namespace bsim
