#pragma once
// A game in the preview's words: each turn's player, plan and the rules' call (the timeline's shots
// row), and the window's game panel (the rules, the two players and who is at the table, the balls
// left, the call of the turn in play, the winner). Pure functions of the rules' record (GameRecord)
// and the time, so they are tested without drawing.
#include <string>
#include <vector>

#include "game.h"
#include "scene.h"

namespace bsim {

struct Shot;

/// How a turn's words are coloured: a foul red, ball in hand amber, a push-out blue, the winner gold.
enum class GameTone { plain, dim, player, foul, in_hand, push_out, winner };

/// The colour of a tone, as 0xAABBGGRR (ImGui's packing), on a dark ground.
unsigned game_tone_color(GameTone tone);

/// The tone of a turn: the winner first, then a foul, a push-out, ball in hand, else plain.
GameTone turn_tone(const GameTurn& turn);

/// A player's initials: "Efren Reyes" -> "ER", "Player 2" -> "P2", "shane" -> "S" (at most three).
std::string name_initials(const std::string& name);

/// A planned shot in a few words: "3 → top-right", "8 → bottom side", "safety", "push-out"; empty when
/// nothing was called.
std::string plan_text(const ShotCall& call, const std::vector<Pocket>& pockets);

/// The rules' call on a turn, no names: the verdict's own words when it has them, else put together
/// from it ("foul: ...; ball in hand", "push-out", "wins the game"); a legal shot that calls nothing
/// says what it made ("made 3, 5") or "no ball made".
std::string turn_call_text(const GameTurn& turn);

/// Player p's name as the record has it, "Player 1" or "Player 2" where it has none.
std::string game_player_name(const GameRecord& record, int player);

/// The call in fewer words, for a narrow section: a foul without its reason ("foul; ball in hand"),
/// the winning shot "wins", else as turn_call_text.
std::string turn_short_call(const GameTurn& turn);

/// The rules' names: "9-ball", "8-ball", "10-ball".
std::string game_rules_name(RackGame rules);

/// 8-ball: the group of each player after turn `through` (from 0), derived from the turns (the first
/// legal shot after the break that makes the ball it called, or with no call the first ball of a group
/// it makes, gives its shooter that group): 0 open, 1 solids, 2 stripes. Always {0, 0} for 9-ball.
std::vector<int> game_groups(const GameRecord& record, int through);

struct GamePanelLine {
  std::string text;
  GameTone tone = GameTone::plain;
  bool balls = false;  ///< the balls left: the window draws GamePanel::on_table as discs after the words up to ':'
};

/// What the window's game panel shows at time t.
struct GamePanel {
  std::vector<GamePanelLine> lines;
  int turn = -1;              ///< the turn in play (the timeline's shot at t), -1 without one
  int at_table = -1;          ///< its player
  std::vector<int> on_table;  ///< the object balls left after the shot in play (painted numbers)
};

/// The panel of `shot`'s game at time t (Timeline::shot_at picks the turn); empty without a game.
/// Lines: the rules and the shot count, each player (the one at the table marked, 8-ball groups),
/// ball in hand when the shooter has it, the plan, the rules' call, the balls left, the winner.
GamePanel game_panel(const Shot& shot, double t);

/// The panel's lines alone.
std::vector<GamePanelLine> game_panel_lines(const Shot& shot, double t);

}  // namespace bsim
