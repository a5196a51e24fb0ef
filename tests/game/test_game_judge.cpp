// The independent judge of a game's events.json (tests/support/game_judge.h) on small hand-written
// logs: a log that follows the WPA rules has no dispute, and each kind of wrong claim (a legal shot
// that hit the wrong ball first, the wrong player at the table, an unclaimed win, a group or the 8 in
// 8-ball) is one dispute at the turn it concerns. And it reads the file the exporter writes.
#include <doctest/doctest.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "game_judge.h"
#include "outputs.h"
#include "random_scenes.h"
#include "shot.h"

using namespace bsim;
using bsim::test::Dispute;
using bsim::test::judge_game;

namespace {

/// One shot of a hand-written log: its events after the strike (each an event's fields from "type"
/// on), the balls it drops ({file index, pocket}) and the cue event's `planned`, if any.
struct LogShot {
  std::vector<std::string> events;
  std::vector<std::pair<int, int>> drops;
  std::string planned;
};

std::string hit(int a, int b) {
  return R"("type": "ball-ball", "balls": [)" + std::to_string(a) + ", " + std::to_string(b) + R"(], "speed": 1)";
}
std::string rail(int ball) {
  return R"("type": "ball-rail", "balls": [)" + std::to_string(ball) + R"(], "rail": 0, "speed": 1)";
}
std::string jaw(int ball) {
  return R"("type": "ball-jaw", "balls": [)" + std::to_string(ball) + R"(], "pocket": 1, "speed": 1)";
}

/// events.json of the shots (shot k struck at 10k + 1 s) with `game` as its game object. `cue`: the
/// cue ball's file index.
std::string log_text(const std::vector<LogShot>& shots, int cue, const std::string& game) {
  std::string events = R"({"index": 0, "time": 0, "type": "start", "shot": 1})", shot_list, drops;
  int index = 1;
  for (std::size_t k = 0; k < shots.size(); ++k) {
    const std::string shot = std::to_string(k + 1), t0 = std::to_string(10 * k + 1);
    events += R"(, {"index": )" + std::to_string(index++) + R"(, "time": )" + t0 + R"(, "type": "cue", "shot": )" +
              shot + R"(, "balls": [)" + std::to_string(cue) + R"(], "speed": 2, "heading": 0)" +
              (shots[k].planned.empty() ? "" : R"(, "planned": )" + shots[k].planned) + "}";
    for (std::size_t j = 0; j < shots[k].events.size(); ++j)
      events += R"(, {"index": )" + std::to_string(index++) + R"(, "time": )" + t0 + "." + std::to_string(j + 1) +
                R"(, "shot": )" + shot + ", " + shots[k].events[j] + "}";
    for (const auto& [ball, pocket] : shots[k].drops)
      drops += std::string(drops.empty() ? "" : ", ") + R"({"time": )" + std::to_string(10 * k + 5) + R"(, "ball": )" +
               std::to_string(ball) + R"(, "pocket": )" + std::to_string(pocket) + "}";
    shot_list += std::string(k ? ", " : "") + R"({"shot": )" + shot + R"(, "cue": )" + t0 + R"(, "rest": )" +
                 std::to_string(10 * k + 8) + "}";
  }
  const std::string end = std::to_string(10 * shots.size() + 1);
  events += R"(, {"index": )" + std::to_string(index) + R"(, "time": )" + end + R"(, "type": "end", "shot": )" +
            std::to_string(shots.size()) + "}";
  return R"({"duration": )" + end + R"(, "events": [)" + events + R"(], "shots": [)" + shot_list +
         R"(], "pocketed": [)" + drops + R"(], "final": [], "game": )" + game + "}";
}

/// One turn of the log's game; `foul` null on a legal shot.
std::string turn(int shot, int player, bool break_shot, const char* foul, const std::string& pocketed, bool continues,
                 const char* in_hand = nullptr, bool push_out = false) {
  const auto flag = [](bool b) { return std::string(b ? "true" : "false"); };
  return R"({"shot": )" + std::to_string(shot) + R"(, "player": )" + std::to_string(player) + R"(, "break": )" +
         flag(break_shot) + R"(, "legal": )" + flag(!foul) + R"(, "foul": )" +
         (foul ? "\"" + std::string(foul) + "\"" : std::string("null")) + R"(, "pocketed": )" + pocketed +
         R"(, "continues": )" + flag(continues) + R"(, "ball_in_hand": )" + flag(in_hand != nullptr) +
         (in_hand ? R"(, "in_hand": ")" + std::string(in_hand) + "\"" : "") +
         (push_out ? R"(, "push_out": true)" : "") + R"(, "call": ""})";
}

std::string game_text(const char* rules, const char* winner, const std::vector<std::string>& turns) {
  std::string list;
  for (const std::string& t : turns) list += (list.empty() ? "" : ", ") + t;
  return R"({"rules": ")" + std::string(rules) + R"(", "players": ["Ann", "Bo"], "winner": )" + winner +
         R"(, "turns": [)" + list + "]}";
}

// 9-ball with four object balls; the cue ball is file index 2, not 0.
//   file index:  0  1  2  3  4
//   number:      1  2  0  3  9
const std::vector<int> kNine = {1, 2, 0, 3, 9};

/// A short 9-ball game by the rules: Ann breaks (the 1 first, in a group collision) and makes the 2;
/// she pushes out and Bo takes the shot, hits the 3 first (a foul: ball in hand for Ann), and Ann makes
/// the 1 and the 9 on a combination.
std::vector<LogShot> nine_shots() {
  LogShot brk{
      {R"("type": "ball-ball", "balls": [0, 1, 2], "speed": 7, "contacts": [{"balls": [0, 2], "time": 1.1, "speed": 7}, {"balls": [0, 1], "time": 1.1001, "speed": 4}])",
       rail(3), jaw(4), rail(2)},
      {{1, 3}},
      ""};
  LogShot push{{rail(2)}, {}, R"({"push_out": true})"};
  LogShot wrong{{hit(2, 3), rail(3)}, {}, R"({"ball": 1, "pocket": 0})"};
  LogShot win{{hit(0, 2), hit(0, 4)}, {{0, 2}, {4, 5}}, R"({"ball": 9, "pocket": 5})"};
  return {brk, push, wrong, win};
}

std::vector<std::string> nine_turns() {
  return {turn(1, 0, true, nullptr, "[2]", true), turn(2, 0, false, nullptr, "[]", false, nullptr, true),
          turn(3, 1, false, "the 3 hit first", "[]", false, "anywhere"), turn(4, 0, false, nullptr, "[1, 9]", false)};
}

std::string disputes_text(const std::vector<Dispute>& d) { return bsim::test::describe(d); }

}  // namespace

TEST_SUITE("game judge") {
  TEST_CASE("a 9-ball log that follows the rules has no dispute") {
    const auto d = judge_game(log_text(nine_shots(), 2, game_text("9ball", "0", nine_turns())), kNine);
    INFO(disputes_text(d));
    CHECK(d.empty());
  }

  TEST_CASE("a shot claimed legal that hit the wrong ball first is one dispute, at its turn") {
    std::vector<std::string> turns = nine_turns();
    turns[2] = turn(3, 1, false, nullptr, "[]", false);
    const auto d = judge_game(log_text(nine_shots(), 2, game_text("9ball", "0", turns)), kNine);
    INFO(disputes_text(d));
    REQUIRE(d.size() == 1);
    CHECK(d[0].turn == 3);
    CHECK(d[0].what.find("legal") != std::string::npos);
    CHECK(d[0].what.find("the cue ball hit the 3 first") != std::string::npos);
  }

  TEST_CASE("the wrong player at the table is one dispute") {
    // After Bo's foul Bo shoots again (and the log gives him the game).
    std::vector<std::string> turns = nine_turns();
    turns[3] = turn(4, 1, false, nullptr, "[1, 9]", false);
    const auto d = judge_game(log_text(nine_shots(), 2, game_text("9ball", "1", turns)), kNine);
    INFO(disputes_text(d));
    REQUIRE(d.size() == 1);
    CHECK(d[0].turn == 4);
    CHECK(d[0].what.find("player 1 shoots; the rules give the table to player 0") != std::string::npos);
  }

  TEST_CASE("a win not claimed is one dispute, about the game") {
    const auto d = judge_game(log_text(nine_shots(), 2, game_text("9ball", "null", nine_turns())), kNine);
    INFO(disputes_text(d));
    REQUIRE(d.size() == 1);
    CHECK(d[0].turn == 0);
    CHECK(d[0].what.find("the rules player 0") != std::string::npos);
  }

  TEST_CASE("9-ball: the wrong balls claimed, a push-out out of place, a turn after the win") {
    std::vector<std::string> turns = nine_turns();
    turns[0] = turn(1, 0, true, nullptr, "[3]", true);
    turns[2] = turn(3, 1, false, "the 3 hit first", "[]", false, "anywhere", true);
    std::vector<LogShot> shots = nine_shots();
    shots.push_back(LogShot{{hit(2, 3), rail(3)}, {}, ""});
    turns.push_back(turn(5, 1, false, nullptr, "[]", false));
    const auto d = judge_game(log_text(shots, 2, game_text("9ball", "0", turns)), kNine);
    INFO(disputes_text(d));
    REQUIRE(d.size() == 3);
    CHECK(d[0].turn == 1);
    CHECK(d[0].what.find("pocketed: the log says [3], the events [2]") != std::string::npos);
    CHECK(d[1].turn == 3);
    CHECK(d[1].what.find("a push-out where the rules allow none") != std::string::npos);
    CHECK(d[2].turn == 5);
    CHECK(d[2].what.find("after the game was won") != std::string::npos);
  }

  TEST_CASE("9-ball: the 9 made on a foul is spotted") {
    // The 1 and the 9: Ann breaks, making the 1 and the 9, and scratches: a foul, the 9 back on the
    // table, ball in hand for Bo, who makes the 9 (the lowest ball) and wins.
    const std::vector<int> numbers = {0, 1, 9};
    LogShot brk{{hit(0, 1), hit(1, 2)}, {{1, 0}, {2, 3}, {0, 2}}, ""};
    LogShot nine{{hit(0, 2)}, {{2, 5}}, ""};
    const std::vector<std::string> turns = {turn(1, 0, true, "scratch", "[1, 9]", false, "anywhere"),
                                            turn(2, 1, false, nullptr, "[9]", false)};
    CHECK(disputes_text(judge_game(log_text({brk, nine}, 0, game_text("9ball", "1", turns)), numbers)) == "");
  }

  TEST_CASE("9-ball: a third foul in a row loses; a breaking foul does not count") {
    // Ann breaks without a legal break (three balls to a cushion, nothing made): a foul that does not
    // count. Bo then scratches, Ann misses, Bo misses, Ann hits the 9 first, Bo too: his third.
    LogShot brk{{hit(2, 0), rail(0), rail(1), rail(3)}, {}, ""};
    LogShot scratch{{hit(2, 0), rail(0)}, {{2, 2}}, ""};
    LogShot miss{{rail(2)}, {}, ""};
    LogShot wrong{{hit(2, 4), rail(4)}, {}, ""};
    const std::vector<std::string> turns = {turn(1, 0, true, "illegal break", "[]", false, "anywhere"),
                                            turn(2, 1, false, "scratch", "[]", false, "anywhere"),
                                            turn(3, 0, false, "no ball hit", "[]", false, "anywhere"),
                                            turn(4, 1, false, "no ball hit", "[]", false, "anywhere"),
                                            turn(5, 0, false, "the 9 hit first", "[]", false, "anywhere"),
                                            turn(6, 1, false, "the 9 hit first", "[]", false)};
    const std::vector<LogShot> shots = {brk, scratch, miss, miss, wrong, wrong};
    CHECK(disputes_text(judge_game(log_text(shots, 2, game_text("9ball", "0", turns)), kNine)) == "");
    const auto d = judge_game(log_text(shots, 2, game_text("9ball", "null", turns)), kNine);
    REQUIRE(d.size() == 1);
    CHECK(d[0].what.find("three fouls in a row") != std::string::npos);
  }

  TEST_CASE("8-ball: the called ball takes the group; the 8 in a pocket not called loses") {
    // file index 0 1 2 3 4; numbers 0 (cue) 1 8 12 13
    const std::vector<int> numbers = {0, 1, 8, 12, 13};
    LogShot brk{{hit(0, 1), hit(1, 4), rail(2)}, {{4, 4}}, ""};
    LogShot solid{{hit(0, 1)}, {{1, 0}}, R"({"ball": 1, "pocket": 0})"};
    LogShot eight{{hit(0, 2)}, {{2, 5}}, R"({"ball": 8, "pocket": 4})"};
    const std::vector<LogShot> shots = {brk, solid, eight};
    const std::vector<std::string> turns = {turn(1, 0, true, nullptr, "[13]", true),
                                            turn(2, 0, false, nullptr, "[1]", true),
                                            turn(3, 0, false, nullptr, "[8]", false)};
    CHECK(disputes_text(judge_game(log_text(shots, 0, game_text("8ball", "1", turns)), numbers)) == "");
    const auto lost = judge_game(log_text(shots, 0, game_text("8ball", "0", turns)), numbers);
    REQUIRE(lost.size() == 1);
    CHECK(lost[0].what.find("the 8 in a pocket not called") != std::string::npos);
    // Made in the called pocket, it wins.
    std::vector<LogShot> called = shots;
    called[2].drops = {{2, 4}};
    CHECK(disputes_text(judge_game(log_text(called, 0, game_text("8ball", "0", turns)), numbers)) == "");
    // Once the solids are Ann's and down, hitting the 12 first is a foul: ball in hand for Bo.
    std::vector<LogShot> stripe = shots;
    stripe[2] = LogShot{{hit(0, 3), rail(3)}, {}, R"({"safety": true})"};
    std::vector<std::string> claimed = turns;
    claimed[2] = turn(3, 0, false, nullptr, "[]", false);
    const auto d = judge_game(log_text(stripe, 0, game_text("8ball", "null", claimed)), numbers);
    REQUIRE(d.size() == 1);
    CHECK(d[0].turn == 3);
    CHECK(d[0].what.find("ball_in_hand: the log says false, the rules true") != std::string::npos);
  }

  TEST_CASE("8-ball: an illegal break is a foul without ball in hand; the 8 on the break does not end the game") {
    const std::vector<int> numbers = {0, 1, 8, 12};
    LogShot weak{{hit(0, 1), rail(1)}, {}, ""};
    LogShot eight_in{{hit(0, 2)}, {{2, 1}}, ""};
    LogShot eight_again{{hit(0, 2), rail(0)}, {}, R"({"safety": true})"};
    // Bo, at the table as it lies, hits the 8 first and makes it: a foul, and the 8 on a foul loses.
    const std::vector<std::string> lost = {turn(1, 0, true, "illegal break", "[]", false),
                                           turn(2, 1, false, "the 8 hit first", "[8]", false)};
    CHECK(disputes_text(judge_game(log_text({weak, eight_in}, 0, game_text("8ball", "0", lost)), numbers)) == "");
    // A break that makes only the 8: spotted, the breaker goes on; hitting it first on an open table
    // is a foul.
    const std::vector<std::string> spotted = {turn(1, 0, true, nullptr, "[8]", true),
                                              turn(2, 0, false, "the 8 hit first", "[]", false, "anywhere")};
    CHECK(disputes_text(
              judge_game(log_text({eight_in, eight_again}, 0, game_text("8ball", "null", spotted)), numbers)) == "");
  }

  TEST_CASE("the judge reads the file the exporter writes") {
    // The cue ball sends the 5 into the top-right corner (pocket 2); the 12 runs into a cushion.
    Scene scene = scenes::standard_table();
    const Vec3 toward = Vec3(0.2788, 0.1938, 0).normalized();
    scene.balls.push_back(
        scenes::ball_at(0, 0.95 - 0.4 * toward.x(), 0.4 - 0.4 * toward.y(), scene.physics, 2 * toward));
    scene.balls.push_back(scenes::ball_at(5, 0.95, 0.4, scene.physics));
    scene.balls.push_back(scenes::ball_at(12, -0.8, -0.3, scene.physics, Vec3(-1.0, 0, 0)));
    auto shot = std::make_unique<Shot>();
    shot->scene = scene;
    shot->timeline = simulate(shot->scene);
    GameRecord game;
    game.players = {"Ann", "Bo"};
    GameTurn t;
    t.verdict.break_shot = true;
    t.verdict.pocketed = {5};
    t.verdict.continues = true;
    game.turns = {t};
    shot->game = game;
    std::ostringstream out;
    write_events_json(*shot, out);
    CHECK(bsim::test::ball_numbers(out.str()) == std::vector<int>{0, 5, 12});
    CHECK(disputes_text(judge_game(out.str(), {0, 5, 12})) == "");
    // Claimed a foul, it is disputed.
    shot->game->turns[0].verdict.legal = false;
    shot->game->turns[0].verdict.foul = "scratch";
    std::ostringstream wrong;
    write_events_json(*shot, wrong);
    CHECK(judge_game(wrong.str(), {0, 5, 12}).size() == 1);
  }
}
