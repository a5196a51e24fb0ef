#include "game_panel.h"

#include <algorithm>
#include <cctype>

#include <imgui.h>

#include "shot.h"

namespace bsim {

namespace {

constexpr const char* kArrow = " \xE2\x86\x92 ";   // →
constexpr const char* kDot = " \xC2\xB7 ";         // ·
constexpr const char* kAtTable = "\xE2\x96\xB6 ";  // ▶

void append(std::string& text, const std::string& part) {
  if (part.empty()) return;
  if (!text.empty()) text += "; ";
  text += part;
}

std::string numbers_text(const std::vector<int>& numbers, const char* between) {
  std::string text;
  for (std::size_t k = 0; k < numbers.size(); ++k) text += (k ? between : "") + std::to_string(numbers[k]);
  return text;
}

std::string group_name(int group) { return group == 1 ? "solids" : group == 2 ? "stripes" : ""; }

/// The group a ball belongs to: 1 solids, 2 stripes, 0 neither (the 8, the cue ball).
int ball_group(int ball) { return ball >= 1 && ball <= 7 ? 1 : ball >= 9 && ball <= 15 ? 2 : 0; }

/// 9-ball: the fouls in a row of `player` after turn `through`, as the last of their turns says.
int fouls_in_row(const GameRecord& record, int player, int through) {
  for (int k = std::min(through, static_cast<int>(record.turns.size()) - 1); k >= 0; --k) {
    const GameTurn& turn = record.turns[static_cast<std::size_t>(k)];
    if (turn.player == player) return turn.verdict.fouls_in_row;
  }
  return 0;
}

std::string player_line(const GameRecord& record, int player, int turn) {
  std::string text = game_player_name(record, player);
  const std::vector<int> groups = game_groups(record, turn);
  if (const std::string g = group_name(groups[static_cast<std::size_t>(player)]); !g.empty())
    text += " \xE2\x80\x94 " + g;
  if (record.rules == RackGame::nine_ball) {
    const int fouls = fouls_in_row(record, player, turn);
    if (fouls > 0) text += kDot + std::to_string(fouls) + (fouls == 1 ? " foul" : " fouls in a row");
  }
  return text;
}

std::string in_hand_text(InHand in_hand) {
  return in_hand == InHand::kitchen    ? "ball in hand behind the head string"
         : in_hand == InHand::anywhere ? "ball in hand"
                                       : "";
}

/// The plan of the turn in play, for the panel.
std::string plan_line(const GameTurn& turn, const std::vector<Pocket>& pockets) {
  const std::string plan = plan_text(turn.planned, pockets);
  if (!plan.empty()) {
    std::string text = (turn.written ? "Called: " : "Plan: ") + plan;
    if (!turn.written && turn.chance > 0 && !turn.planned.safety && !turn.planned.push_out)
      text += " (" + std::to_string(static_cast<int>(turn.chance * 100 + 0.5)) + " %)";
    return text;
  }
  if (turn.verdict.break_shot) return "The break";
  return turn.written ? "A written shot" : "";
}

/// The game's end, for the panel's last line: the winner, or the shot limit.
GamePanelLine ending_line(const GameRecord& record, const GameTurn& turn, bool last) {
  if (turn.verdict.winner) return {game_player_name(record, *turn.verdict.winner) + " wins the game", GameTone::winner};
  if (last && record.winner) return {game_player_name(record, *record.winner) + " wins the game", GameTone::winner};
  if (last && record.shot_limit)
    return {"No winner: the game stopped at its limit of " + std::to_string(record.turns.size()) + " shots",
            GameTone::dim};
  return {};
}

}  // namespace

unsigned game_tone_color(GameTone tone) {
  switch (tone) {
    case GameTone::plain: return IM_COL32(230, 232, 236, 255);
    case GameTone::dim: return IM_COL32(150, 156, 168, 255);
    case GameTone::player: return IM_COL32(140, 220, 255, 255);
    case GameTone::foul: return IM_COL32(245, 64, 56, 255);
    case GameTone::in_hand: return IM_COL32(255, 150, 50, 255);
    case GameTone::push_out: return IM_COL32(120, 150, 255, 255);
    case GameTone::winner: return IM_COL32(255, 204, 40, 255);
  }
  return IM_COL32(230, 232, 236, 255);
}

GameTone turn_tone(const GameTurn& turn) {
  const TurnVerdict& v = turn.verdict;
  if (v.winner) return GameTone::winner;
  if (!v.legal || !v.foul.empty()) return GameTone::foul;
  if (v.push_out || turn.planned.push_out) return GameTone::push_out;
  if (v.in_hand != InHand::none) return GameTone::in_hand;
  return GameTone::plain;
}

std::string name_initials(const std::string& name) {
  std::string initials;
  int letters = 0;
  for (std::size_t k = 0; k < name.size() && letters < 3;) {
    if (std::isspace(static_cast<unsigned char>(name[k]))) {
      ++k;
      continue;
    }
    // A word's first letter: one byte, or a whole UTF-8 sequence.
    std::size_t end = k + 1;
    while (end < name.size() && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) ++end;
    initials += end == k + 1 ? std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(name[k]))))
                             : name.substr(k, end - k);
    ++letters;
    while (end < name.size() && !std::isspace(static_cast<unsigned char>(name[end]))) ++end;
    k = end;
  }
  return initials;
}

std::string plan_text(const ShotCall& call, const std::vector<Pocket>& pockets) {
  if (call.push_out) return "push-out";
  if (call.safety) return "safety";
  if (call.ball < 0) return "";
  std::string text = std::to_string(call.ball);
  if (call.pocket >= 0) {
    std::string pocket = pocket_short_name(pockets, call.pocket);
    if (pocket.ends_with(" corner")) pocket.resize(pocket.size() - 7);
    text += kArrow + pocket;
  }
  return text;
}

std::string turn_call_text(const GameTurn& turn) {
  const TurnVerdict& v = turn.verdict;
  if (!v.call.empty()) return v.call;
  std::string text;
  if (!v.foul.empty() || !v.legal) append(text, "foul" + (v.foul.empty() ? std::string() : ": " + v.foul));
  if (v.push_out) append(text, "push-out");
  append(text, in_hand_text(v.in_hand));
  if (!v.spotted.empty()) append(text, numbers_text(v.spotted, ", ") + " spotted");
  if (v.winner) append(text, "wins the game");
  if (!text.empty()) return text;
  return v.pocketed.empty() ? "no ball made" : "made " + numbers_text(v.pocketed, ", ");
}

std::string turn_short_call(const GameTurn& turn) {
  const TurnVerdict& v = turn.verdict;
  if (v.foul.empty() && v.legal) return v.winner ? "wins" : turn_call_text(turn);
  std::string text = "foul";
  append(text, in_hand_text(v.in_hand));
  if (!v.spotted.empty()) append(text, numbers_text(v.spotted, ", ") + " spotted");
  if (v.winner) append(text, "wins the game");
  return text;
}

std::string game_player_name(const GameRecord& record, int player) {
  if (player >= 0 && player < static_cast<int>(record.players.size()) &&
      !record.players[static_cast<std::size_t>(player)].empty())
    return record.players[static_cast<std::size_t>(player)];
  return "Player " + std::to_string(player + 1);
}

std::string game_rules_name(RackGame rules) {
  switch (rules) {
    case RackGame::eight_ball: return "8-ball";
    case RackGame::nine_ball: return "9-ball";
    case RackGame::ten_ball: return "10-ball";
  }
  return "";
}

std::vector<int> game_groups(const GameRecord& record, int through) {
  std::vector<int> groups{0, 0};
  if (record.rules != RackGame::eight_ball) return groups;
  const int last = std::min(through, static_cast<int>(record.turns.size()) - 1);
  for (int k = 0; k <= last; ++k) {
    const GameTurn& turn = record.turns[static_cast<std::size_t>(k)];
    const TurnVerdict& v = turn.verdict;
    if (v.break_shot || !v.legal || v.pocketed.empty() || turn.player < 0 || turn.player > 1) continue;
    int group = 0;
    if (turn.planned.ball >= 0) {
      if (std::find(v.pocketed.begin(), v.pocketed.end(), turn.planned.ball) != v.pocketed.end())
        group = ball_group(turn.planned.ball);
    } else {
      for (int ball : v.pocketed)
        if ((group = ball_group(ball)) != 0) break;
    }
    if (group == 0) continue;
    groups[static_cast<std::size_t>(turn.player)] = group;
    groups[static_cast<std::size_t>(1 - turn.player)] = 3 - group;
    return groups;
  }
  return groups;
}

namespace {

/// The object balls on the table before the first shot, ascending.
std::vector<int> racked(const Scene& scene) {
  std::vector<int> out;
  for (const Ball& b : scene.balls)
    if (b.number > 0) out.push_back(b.number);
  std::sort(out.begin(), out.end());
  return out;
}

/// The last turn whose shot's balls rest at time t, or -1.
int last_called(const Shot& shot, double t, int count) {
  const std::vector<ShotSpan>& spans = shot.timeline.shots();
  int called = -1;
  for (int k = 0; k < count && k < static_cast<int>(spans.size()); ++k)
    if (spans[static_cast<std::size_t>(k)].rest <= t) called = k;
  return called;
}

}  // namespace

GamePanel game_panel(const Shot& shot, double t) {
  GamePanel panel;
  if (!shot.game) return panel;
  const GameRecord& record = *shot.game;
  const int count = static_cast<int>(record.turns.size());
  panel.turn = count == 0 ? -1 : std::clamp(shot.timeline.shot_at(t), 0, count - 1);
  std::string head = game_rules_name(record.rules);
  if (panel.turn >= 0)
    head += kDot + std::string("shot ") + std::to_string(panel.turn + 1) + " of " + std::to_string(count);
  panel.lines.push_back({head, GameTone::plain});
  if (panel.turn < 0) {
    for (int p = 0; p < 2; ++p) panel.lines.push_back({"   " + player_line(record, p, -1), GameTone::dim});
    return panel;
  }
  const GameTurn& turn = record.turns[static_cast<std::size_t>(panel.turn)];
  panel.at_table = turn.player;
  for (int p = 0; p < 2; ++p)
    panel.lines.push_back({(p == turn.player ? kAtTable : "   ") + player_line(record, p, panel.turn),
                           p == turn.player ? GameTone::player : GameTone::dim});
  if (panel.turn > 0) {
    const InHand in_hand = record.turns[static_cast<std::size_t>(panel.turn - 1)].verdict.in_hand;
    if (in_hand != InHand::none) {
      std::string text = in_hand_text(in_hand);
      text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
      panel.lines.push_back({text, GameTone::in_hand});
    }
  }
  if (const std::string plan = plan_line(turn, shot.scene.pockets); !plan.empty())
    panel.lines.push_back({plan, GameTone::plain});
  // The rules' call of the last shot whose balls rest (the winner's own line says "wins the game"), and
  // the table it left: the panel tells no more than the viewer has seen, and the call stays up while
  // the next shooter comes to the table.
  const int called = last_called(shot, t, count);
  if (called >= 0) {
    const GameTurn& last = record.turns[static_cast<std::size_t>(called)];
    const GameTone tone = turn_tone(last);
    const std::string call = turn_call_text(last);
    if (!call.empty() && call != "wins the game")
      panel.lines.push_back({(called == panel.turn ? "" : "Shot " + std::to_string(called + 1) + ": ") + call,
                             tone == GameTone::winner ? GameTone::plain : tone});
  }
  const bool done = called == panel.turn;
  panel.on_table = called >= 0 ? record.turns[static_cast<std::size_t>(called)].on_table : racked(shot.scene);
  panel.lines.push_back(
      {"On the table: " + (panel.on_table.empty() ? std::string("none") : numbers_text(panel.on_table, " ")),
       GameTone::plain, !panel.on_table.empty()});
  if (GamePanelLine end = ending_line(record, turn, done && panel.turn == count - 1); !end.text.empty())
    panel.lines.push_back(std::move(end));
  return panel;
}

std::vector<GamePanelLine> game_panel_lines(const Shot& shot, double t) { return game_panel(shot, t).lines; }

}  // namespace bsim
