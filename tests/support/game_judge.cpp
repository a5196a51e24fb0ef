// The independent judge of a played game (game_judge.h): the WPA World Standard Rules of 9-ball and
// 8-ball, written from the rules, applied to the facts read from events.json.
#include "game_judge.h"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>

namespace bsim::test {

namespace {

using nlohmann::json;

/// What one shot did, read from its events and drops alone. Balls by painted number.
struct Facts {
  int struck = -1;                      ///< the ball the stick struck
  int first_hit = -1;                   ///< the first ball the cue ball touched; -1: none
  bool cushion_after_hit = false;       ///< any ball met a cushion or a jaw after that first contact
  int object_balls_to_cushion = 0;      ///< distinct object balls that met a cushion or a jaw
  std::vector<int> made, made_pockets;  ///< object balls made, in the order they dropped, and where
  bool scratch = false;                 ///< the cue ball went into a pocket
};

/// The shooter's call, from the `planned` of the shot's cue event: none (a written shot), a ball and
/// a pocket, or a safety.
struct Call {
  int ball = -1, pocket = -1;
  bool safety = false;
};

/// What a turn of the log claims.
struct Claim {
  int shot = 0, player = 0;
  bool break_shot = false, legal = true, foul = false, continues = false, ball_in_hand = false, push_out = false;
  std::vector<int> pocketed;
  std::string in_hand;  ///< "kitchen", "anywhere" or "" (not given)
};

enum class Hand { none, kitchen, anywhere };

/// The rules' verdict on a shot.
struct Verdict {
  bool legal = true;
  bool legal_free = false;  ///< 8-ball, a game lost on the 8 by an otherwise legal shot: either reading
  std::string why;          ///< the rule broken, or why the game ended
  bool continues = false;
  bool continues_free = false;  ///< a legal push-out: the incoming player chooses
  Hand in_hand = Hand::none;
  std::optional<int> winner;
};

/// The game between shots, as the judge keeps it.
struct State {
  bool nine = true;
  std::set<int> up;  ///< object balls on the table
  bool break_next = true;
  bool push_out_next = false;
  int group[2] = {0, 0};  ///< 8-ball: 0 open, 1 solids, 2 stripes
  int fouls[2] = {0, 0};  ///< 9-ball: fouls in a row
  std::optional<int> winner;
  int won_at = 0;
  std::string won_why;
};

int number_of(const std::vector<int>& numbers, int index) {
  if (index < 0 || index >= static_cast<int>(numbers.size()))
    throw std::runtime_error("ball index " + std::to_string(index) + " is not in the numbering");
  return numbers[static_cast<std::size_t>(index)];
}

std::string ball_name(int number) { return number == 0 ? "the cue ball" : "the " + std::to_string(number); }

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

/// The ball the cue ball meets in a ball-ball event (its first contact naming the cue ball), or -1.
int cue_contact(const json& e, int cue) {
  if (e.contains("contacts")) {
    for (const json& c : e.at("contacts")) {
      const int a = c.at("balls").at(0), b = c.at("balls").at(1);
      if (a == cue) return b;
      if (b == cue) return a;
    }
    return -1;
  }
  const json& balls = e.at("balls");
  if (balls.size() != 2) return -1;
  if (balls[0] == cue) return balls[1];
  if (balls[1] == cue) return balls[0];
  return -1;
}

/// The facts of shot `shot` (from 1): its events, and the drops between its strike and the next one's.
Facts shot_facts(const json& doc, int shot, const std::vector<int>& numbers, int cue) {
  Facts f;
  std::set<int> to_cushion;
  for (const json& e : doc.at("events")) {
    if (e.at("shot").get<int>() != shot) continue;
    const std::string type = e.at("type");
    if (type == "cue") {
      f.struck = number_of(numbers, e.at("balls").at(0));
    } else if (type == "ball-ball" && f.first_hit < 0) {
      const int other = cue_contact(e, cue);
      if (other >= 0) f.first_hit = number_of(numbers, other);
    } else if (type == "ball-rail" || type == "ball-jaw") {
      const int ball = number_of(numbers, e.at("balls").at(0));
      if (f.first_hit >= 0) f.cushion_after_hit = true;
      if (ball != 0) to_cushion.insert(ball);
    }
  }
  f.object_balls_to_cushion = static_cast<int>(to_cushion.size());
  const json& shots = doc.at("shots");
  const double from = shots.at(static_cast<std::size_t>(shot - 1)).at("cue");
  const double to = static_cast<std::size_t>(shot) < shots.size()
                        ? shots[static_cast<std::size_t>(shot)].at("cue").get<double>()
                        : std::numeric_limits<double>::infinity();
  for (const json& d : doc.at("pocketed")) {
    const double t = d.at("time");
    if (t < from || t >= to) continue;
    const int ball = number_of(numbers, d.at("ball"));
    if (ball == 0) {
      f.scratch = true;
    } else {
      f.made.push_back(ball);
      f.made_pockets.push_back(d.at("pocket"));
    }
  }
  return f;
}

/// The call of shot `shot` (from 1): its cue event's `planned`.
Call shot_call(const json& doc, int shot) {
  Call call;
  for (const json& e : doc.at("events")) {
    if (e.at("shot").get<int>() != shot || e.at("type") != "cue" || !e.contains("planned")) continue;
    const json& p = e.at("planned");
    call.safety = p.value("safety", false);
    call.ball = p.value("ball", -1);
    call.pocket = p.value("pocket", -1);
  }
  return call;
}

Claim read_claim(const json& t) {
  Claim c;
  c.shot = t.at("shot");
  c.player = t.at("player");
  c.break_shot = t.at("break");
  c.legal = t.at("legal");
  c.foul = !t.at("foul").is_null();
  c.pocketed = t.at("pocketed").get<std::vector<int>>();
  c.continues = t.at("continues");
  c.ball_in_hand = t.at("ball_in_hand");
  c.in_hand = t.value("in_hand", "");
  c.push_out = t.value("push_out", false);
  return c;
}

void foul(Verdict& v, std::string why) {
  if (!v.legal) return;  // the first rule broken names the foul
  v.legal = false;
  v.why = std::move(why);
}

/// The fouls every shot can commit (General Rules): no ball hit, the wrong ball first, a scratch, no
/// ball made and no cushion after the first contact. `targets`: the balls legal to hit first.
void standard_fouls(Verdict& v, const Facts& f, const std::set<int>& targets) {
  if (f.scratch) foul(v, "the cue ball went into a pocket");
  if (f.first_hit < 0) foul(v, "the cue ball hit no ball");
  if (f.first_hit >= 0 && !targets.count(f.first_hit)) foul(v, "the cue ball hit " + ball_name(f.first_hit) + " first");
  if (f.made.empty() && !f.cushion_after_hit) foul(v, "no ball made and no cushion after the first contact");
}

/// 9-ball: the lowest ball first; a legal break (the 1 first, a ball made or four to a cushion); the 9
/// on a legal shot wins, on a foul it is spotted; ball in hand anywhere after a foul; the push-out; three
/// fouls in a row (breaking fouls not counted) lose.
Verdict nine_ball(State& s, const Facts& f, int p, bool push_out) {
  Verdict v;
  const std::set<int> lowest = s.up.empty() ? std::set<int>{} : std::set<int>{*s.up.begin()};
  if (push_out) {
    if (f.scratch) foul(v, "the cue ball went into a pocket");
  } else {
    standard_fouls(v, f, lowest);
    if (s.break_next && f.made.empty() && f.object_balls_to_cushion < 4)
      foul(v, "the break made no ball and drove fewer than four balls to a cushion");
  }
  for (const int b : f.made) s.up.erase(b);
  const bool nine_made = contains(f.made, 9);
  if (!v.legal) {
    v.in_hand = Hand::anywhere;
    if (nine_made) s.up.insert(9);
    if (!s.break_next && ++s.fouls[p] >= 3) {
      v.winner = 1 - p;
      v.why = "three fouls in a row";
    }
  } else {
    s.fouls[p] = 0;
    if (push_out) {
      v.continues_free = true;
      if (nine_made) s.up.insert(9);
    } else if (nine_made) {
      v.winner = p;
      v.why = "the 9 made on a legal shot";
    } else {
      v.continues = !f.made.empty();
    }
  }
  s.push_out_next = s.break_next && !f.scratch;
  s.break_next = false;
  return v;
}

/// 8-ball, the break: a ball made or four to a cushion, else a foul (the table taken as it lies); a
/// scratch gives ball in hand behind the head string; the 8 made is spotted; the table stays open.
Verdict eight_ball_break(State& s, const Facts& f) {
  Verdict v;
  for (const int b : f.made) s.up.erase(b);
  if (contains(f.made, 8)) s.up.insert(8);
  if (f.scratch) {
    foul(v, "the cue ball went into a pocket on the break");
    v.in_hand = Hand::kitchen;
  }
  if (f.made.empty() && f.object_balls_to_cushion < 4)
    foul(v, "the break made no ball and drove fewer than four balls to a cushion");
  v.continues = v.legal && !f.made.empty();
  s.break_next = false;
  return v;
}

/// 8-ball after the break: the shooter's group first (any but the 8 on an open table; the 8 once the
/// group is down); the called ball in its pocket goes on and, on an open table, takes its group; the 8
/// wins made legally in its called pocket once the group is down, and loses made any other way.
Verdict eight_ball(State& s, const Facts& f, int p, const Call& call) {
  if (s.break_next) return eight_ball_break(s, f);
  Verdict v;
  std::set<int> targets;
  for (const int b : s.up)
    if (b != 8 && (s.group[p] == 0 || (s.group[p] == 1) == (b < 8))) targets.insert(b);
  if (targets.empty()) targets.insert(8);
  const bool on_eight = targets == std::set<int>{8};
  standard_fouls(v, f, targets);
  for (const int b : f.made) s.up.erase(b);
  const auto eight = std::find(f.made.begin(), f.made.end(), 8);
  if (eight != f.made.end()) {
    const int pocket = f.made_pockets[static_cast<std::size_t>(eight - f.made.begin())];
    const bool called = !call.safety && (call.ball < 0 || (call.ball == 8 && call.pocket == pocket));
    if (v.legal && on_eight && called) {
      v.winner = p;
      v.why = "the 8 made in its called pocket";
    } else {
      v.legal_free = v.legal;
      v.winner = 1 - p;
      v.why = !v.legal    ? "the 8 made on a foul"
              : !on_eight ? "the 8 made before the group"
                          : "the 8 in a pocket not called";
    }
    return v;
  }
  if (!v.legal) {
    v.in_hand = Hand::anywhere;
    return v;
  }
  for (std::size_t k = 0; k < f.made.size() && !call.safety; ++k) {
    const int b = f.made[k];
    if (!targets.count(b) || (call.ball >= 0 && (call.ball != b || call.pocket != f.made_pockets[k]))) continue;
    v.continues = true;
    if (s.group[p] == 0) {
      s.group[p] = b < 8 ? 1 : 2;
      s.group[1 - p] = 3 - s.group[p];
    }
    break;
  }
  return v;
}

std::string yes(bool b) { return b ? "true" : "false"; }

std::string list(const std::vector<int>& v) {
  std::string out = "[";
  for (std::size_t k = 0; k < v.size(); ++k) out += (k ? ", " : "") + std::to_string(v[k]);
  return out + "]";
}

/// Where the claim and the verdict differ, in words.
std::vector<std::string> differences(const Claim& c, const Verdict& v, const Facts& f) {
  std::vector<std::string> out;
  const std::string why = v.why.empty() ? "" : " (" + v.why + ")";
  if (!v.legal_free && c.legal != v.legal)
    out.push_back("legal: the log says " + yes(c.legal) + ", the rules " + yes(v.legal) + why);
  if (!v.legal_free && c.foul == v.legal)
    out.push_back(std::string("foul: the log ") + (c.foul ? "names one" : "names none") + why);
  if (c.pocketed != f.made)
    out.push_back("pocketed: the log says " + list(c.pocketed) + ", the events " + list(f.made));
  if (v.winner) return out;  // the game is over: no next shot to continue or place the cue ball for
  if (!v.continues_free && c.continues != v.continues)
    out.push_back("continues: the log says " + yes(c.continues) + ", the rules " + yes(v.continues) + why);
  const bool in_hand = v.in_hand != Hand::none;
  if (c.ball_in_hand != in_hand)
    out.push_back("ball_in_hand: the log says " + yes(c.ball_in_hand) + ", the rules " + yes(in_hand) + why);
  const std::string where = v.in_hand == Hand::kitchen ? "kitchen" : "anywhere";
  if (in_hand && !c.in_hand.empty() && c.in_hand != where)
    out.push_back("in_hand: the log says " + c.in_hand + ", the rules " + where);
  return out;
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
  return out;
}

/// Judges turn `k` (from 0) and moves the game on. Returns the player the log must give the next shot.
int judge_turn(const json& doc, const Claim& c, int k, int expected, State& s, const std::vector<int>& numbers,
               std::vector<Dispute>& out) {
  std::vector<std::string> diff;
  const int shot = k + 1;
  if (c.shot != shot)
    diff.push_back("shot: the log says " + std::to_string(c.shot) + ", turn " + std::to_string(shot) + " is shot " +
                   std::to_string(shot));
  if (c.player != expected)
    diff.push_back("player " + std::to_string(c.player) + " shoots; the rules give the table to player " +
                   std::to_string(expected));
  if (c.break_shot != s.break_next)
    diff.push_back("break: the log says " + yes(c.break_shot) + ", the rules " + yes(s.break_next));
  const int cue = static_cast<int>(std::find(numbers.begin(), numbers.end(), 0) - numbers.begin());
  const Facts f = shot_facts(doc, shot, numbers, cue);
  if (f.struck != 0) diff.push_back("the stick struck " + ball_name(f.struck) + ", not the cue ball");
  bool push_out = c.push_out;
  if (push_out && (!s.nine || !s.push_out_next)) {
    diff.push_back("a push-out where the rules allow none");
    push_out = false;
  }
  const int p = c.player == 1 ? 1 : 0;
  const Verdict v = s.nine ? nine_ball(s, f, p, push_out) : eight_ball(s, f, p, shot_call(doc, shot));
  for (const std::string& d : differences(c, v, f)) diff.push_back(d);
  if (v.winner) {
    s.winner = v.winner;
    s.won_at = shot;
    s.won_why = v.why;
  }
  if (!diff.empty()) out.push_back({shot, joined(diff)});
  return c.continues ? p : 1 - p;
}

void judge_document(const json& doc, const std::vector<int>& numbers, std::vector<Dispute>& out) {
  if (!doc.contains("game")) {
    out.push_back({0, "the file has no game"});
    return;
  }
  const json& game = doc.at("game");
  const std::string rules = game.at("rules");
  if (rules != "9ball" && rules != "8ball") {
    out.push_back({0, "unknown rules \"" + rules + "\""});
    return;
  }
  if (std::count(numbers.begin(), numbers.end(), 0) != 1) {
    out.push_back({0, "the numbering has no single cue ball"});
    return;
  }
  State s;
  s.nine = rules == "9ball";
  for (const int n : numbers)
    if (n != 0) s.up.insert(n);
  const json& turns = game.at("turns");
  if (turns.size() != doc.at("shots").size())
    out.push_back(
        {0, std::to_string(turns.size()) + " turns for " + std::to_string(doc.at("shots").size()) + " shots"});
  int expected = 0;
  for (std::size_t k = 0; k < turns.size() && k < doc.at("shots").size(); ++k) {
    if (s.winner) {
      out.push_back({static_cast<int>(k) + 1, "a turn after the game was won at turn " + std::to_string(s.won_at)});
      break;
    }
    expected = judge_turn(doc, read_claim(turns[k]), static_cast<int>(k), expected, s, numbers, out);
  }
  const json& winner = game.at("winner");
  const std::optional<int> claimed = winner.is_null() ? std::nullopt : std::optional<int>(winner.get<int>());
  if (claimed != s.winner) {
    const auto name = [](std::optional<int> w) { return w ? "player " + std::to_string(*w) : std::string("none"); };
    out.push_back({0, "winner: the log says " + name(claimed) + ", the rules " + name(s.winner) +
                          (s.winner ? " (turn " + std::to_string(s.won_at) + ": " + s.won_why + ")" : "")});
  }
}

}  // namespace

std::vector<Dispute> judge_game(const std::string& events_json, const std::vector<int>& numbers) {
  std::vector<Dispute> out;
  try {
    judge_document(json::parse(events_json), numbers, out);
  } catch (const std::exception& e) {
    out.push_back({0, std::string("the file cannot be judged: ") + e.what()});
  }
  return out;
}

std::vector<int> ball_numbers(const std::string& events_json) {
  const json doc = json::parse(events_json);
  std::vector<int> numbers;
  for (const json& b : doc.at("final")) numbers.push_back(b.at("number"));
  return numbers;
}

std::string describe(const std::vector<Dispute>& disputes) {
  std::string out;
  for (const Dispute& d : disputes)
    out += (d.turn ? "turn " + std::to_string(d.turn) : std::string("game")) + ": " + d.what + "\n";
  return out;
}

}  // namespace bsim::test
