#include "caption.h"

#include <algorithm>

namespace bsim {

namespace {

std::string joined(const std::vector<std::string>& parts, const char* between) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : between) + part;
  return text;
}

const std::string& name_of(const GameRecord& record, int player) {
  static const std::string kNobody;
  return player >= 0 && player < static_cast<int>(record.players.size())
             ? record.players[static_cast<std::size_t>(player)]
             : kNobody;
}

/// The rules' foul in the caption's words: the reason, then what follows from it.
CaptionCall foul_call(const GameRecord& record, const TurnVerdict& v) {
  std::vector<std::string> parts = {v.foul};
  for (int ball : v.spotted) parts.push_back("the " + std::to_string(ball) + " is spotted");
  if (v.winner && record.rules != RackGame::eight_ball) parts.push_back("third foul in a row");
  if (v.in_hand == InHand::anywhere) parts.push_back("ball in hand");
  if (v.in_hand == InHand::kitchen) parts.push_back("ball in hand behind the head string");
  if (!v.winner && v.fouls_in_row == 2 && record.rules != RackGame::eight_ball) parts.push_back("second foul in a row");
  return {CaptionCall::Kind::foul, "FOUL", joined(parts, " \xC2\xB7 ")};  // a middle dot between
}

CaptionCall winner_call(const GameRecord& record, int winner) {
  return {CaptionCall::Kind::winner, "WINNER", name_of(record, winner) + " wins the game"};
}

/// What the rules said once turn `k`'s balls came to rest.
std::vector<CaptionCall> aftermath(const GameRecord& record, int k) {
  const GameTurn& turn = record.turns[static_cast<std::size_t>(k)];
  const TurnVerdict& v = turn.verdict;
  std::vector<CaptionCall> calls;
  if (!v.foul.empty()) calls.push_back(foul_call(record, v));
  if (v.push_out) {
    // The incoming player answers: takes the table, or hands it back (the pusher goes on).
    const std::string incoming = name_of(record, 1 - turn.player);
    calls.push_back({CaptionCall::Kind::push_out, "PUSH-OUT",
                     incoming + (v.continues ? " hands the table back" : " takes the table")});
  }
  if (v.foul.empty() && !v.spotted.empty() && !v.winner)
    calls.push_back({CaptionCall::Kind::push_out, "SPOTTED",
                     "the " + std::to_string(v.spotted.front()) + " goes back on the foot spot"});
  if (v.call == "solids" || v.call == "stripes")
    calls.push_back({CaptionCall::Kind::push_out, v.call == "solids" ? "SOLIDS" : "STRIPES",
                     name_of(record, turn.player) + " plays the " + v.call});
  if (v.winner) calls.push_back(winner_call(record, *v.winner));
  if (k + 1 == static_cast<int>(record.turns.size()) && record.shot_limit)
    calls.push_back({CaptionCall::Kind::stopped, "NO WINNER",
                     "stopped at its limit of " + std::to_string(record.turns.size()) + " shots"});
  return calls;
}

/// The balls on the table at t within shot k: those up before it, less those dropped so far; once it
/// has settled, the rules' count.
std::vector<int> balls_at(const GameRecord& record, const Timeline& timeline, const Scene& scene,
                          const std::vector<int>& rack, int k, double t) {
  const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(k)];
  if (t >= timeline.settled(k)) return record.turns[static_cast<std::size_t>(k)].on_table;
  std::vector<int> balls = k == 0 ? rack : record.turns[static_cast<std::size_t>(k - 1)].on_table;
  for (const PocketDrop& drop : timeline.pocket_drops()) {
    if (drop.time < span.start || drop.time > t || drop.ball < 0 || drop.ball >= static_cast<int>(scene.balls.size()))
      continue;
    std::erase(balls, scene.balls[static_cast<std::size_t>(drop.ball)].number);
  }
  return balls;
}

}  // namespace

Caption caption_at(const GameRecord& record, const Timeline& timeline, const Scene& scene, double t, bool replay) {
  Caption c;
  c.rules = record.rules;
  c.players = record.players;
  c.replay = replay;
  for (const Ball& ball : scene.balls)
    if (ball.number > 0) c.rack.push_back(ball.number);
  std::sort(c.rack.begin(), c.rack.end());
  c.on_table = c.rack;
  const int turns = std::min(static_cast<int>(record.turns.size()), timeline.shot_count());
  if (turns > 0) {
    const int k = std::clamp(timeline.shot_at(t), 0, turns - 1);
    const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(k)];
    const GameTurn& turn = record.turns[static_cast<std::size_t>(k)];
    c.shot = k;
    c.at_table = turn.player;
    c.on_table = balls_at(record, timeline, scene, c.rack, k, t);
    // The referee calls a shot once its balls have stopped (spin in place changes nothing).
    const bool decided = t >= timeline.settled(k);
    if (decided)
      c.calls = aftermath(record, k);
    else if (k > 0 && t < span.cue)
      c.calls = aftermath(record, k - 1);  // the last shot's call stays until this shot's stroke
    if (!decided && turn.verdict.push_out)
      c.calls.push_back({CaptionCall::Kind::push_out, "PUSH-OUT", name_of(record, turn.player) + " pushes out"});
  }
  const auto has_winner = [&c] {
    return std::any_of(c.calls.begin(), c.calls.end(),
                       [](const CaptionCall& call) { return call.kind == CaptionCall::Kind::winner; });
  };
  if (replay && record.winner && !has_winner()) c.calls.push_back(winner_call(record, *record.winner));
  return c;
}

std::string caption_text(const Caption& c) {
  std::vector<std::string> parts;
  for (std::size_t p = 0; p < c.players.size(); ++p)
    parts.push_back(c.players[p] + (static_cast<int>(p) == c.at_table ? "*" : ""));
  std::vector<std::string> balls;
  for (int ball : c.on_table) balls.push_back(std::to_string(ball));
  parts.push_back(joined(balls, " "));
  for (const CaptionCall& call : c.calls) parts.push_back(call.title + ": " + call.text);
  if (c.replay) parts.push_back("REPLAY");
  return joined(parts, " | ");
}

const char* caption_game_name(RackGame rules) {
  switch (rules) {
    case RackGame::eight_ball: return "8-BALL";
    case RackGame::nine_ball: return "9-BALL";
    case RackGame::ten_ball: return "10-BALL";
  }
  return "";
}

}  // namespace bsim
