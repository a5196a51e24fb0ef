// The rules of 9-ball and 8-ball as a state machine over what each shot did.
// Sources: the WPA World Standard Rules (World Pool-Billiard Association: the General Rules, the rules of
// 9-ball and of 8-ball); pooltool's `ruleset` (Kiefl: `ruleset/utils.py` for the queries on a shot's
// events, `nine_ball.py` and `eight_ball.py` for their order); FastFiz `Rules.cpp` (Leckie & Greenspan:
// the state between shots, the fouls in a row, the push-out, the 9 spotted after a foul).
#include "rules.h"

#include <algorithm>
#include <limits>
#include <set>

namespace bsim {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

/// The painted number of file-order ball `index`; -1 for an index the scene does not have.
int painted(const std::vector<Ball>& balls, int index) {
  return index >= 0 && index < static_cast<int>(balls.size()) ? balls[static_cast<std::size_t>(index)].number : -1;
}

/// A ball-ball event's contacts in the order they began (a pair without a contact list is one at the
/// event's time).
std::vector<Contact> contacts_of(const Event& e) {
  if (!e.contacts.empty()) return e.contacts;
  std::vector<Contact> out;
  for (std::size_t i = 1; i < e.balls.size(); ++i) out.push_back(Contact{e.balls[0], e.balls[i], e.time, 0, {0, 0, 0}});
  return out;
}

/// The strike of shot `shot` and the next shot's strike (kNever when none).
void shot_window(const std::vector<Event>& events, int shot, double& start, double& end) {
  start = kNever;
  end = kNever;
  for (const Event& e : events) {
    if (e.type != EventType::cue) continue;
    if (e.shot == shot) start = std::min(start, e.time);
    if (e.shot > shot) end = std::min(end, e.time);
  }
}

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

void remove_ball(std::vector<int>& v, int x) { v.erase(std::remove(v.begin(), v.end(), x), v.end()); }

void add_ball(std::vector<int>& v, int x) {
  if (!contains(v, x)) v.insert(std::upper_bound(v.begin(), v.end(), x), x);
}

std::string the(int ball) { return "the " + std::to_string(ball); }

/// 8-ball groups: 1 solids (1-7), 2 stripes (9-15), 0 neither.
int group_of(int ball) { return ball >= 1 && ball <= 7 ? 1 : ball >= 9 && ball <= 15 ? 2 : 0; }
std::string group_name(int group) { return group == 1 ? "solids" : "stripes"; }
std::string group_one(int group) { return group == 1 ? "a solid" : "a stripe"; }

const char* const kScratch = "the cue ball went into a pocket";
const char* const kMissed = "the cue ball missed every ball";
const char* const kIllegalBreak = "an illegal break: no ball made and fewer than four balls to a cushion";

std::string no_cushion(int first_hit) { return "no ball reached a cushion after the cue ball hit " + the(first_hit); }

/// 9-ball (and 10-ball): the rule a shot broke, or "" (the push-out is judged apart).
std::string rotation_foul(const ShotFacts& f, int lowest, bool break_shot) {
  if (f.first_hit < 0) return kMissed;
  if (f.first_hit != lowest) {
    if (break_shot) return "the break did not hit " + the(lowest) + " first";
    return "the cue ball hit " + the(f.first_hit) + " first, not " + the(lowest);
  }
  if (f.scratch) return kScratch;
  if (break_shot) return f.pocketed.empty() && f.object_balls_to_cushion < 4 ? kIllegalBreak : "";
  if (f.pocketed.empty() && !f.cushion_after_hit) return no_cushion(f.first_hit);
  return "";
}

/// 8-ball after the break: the rule a shot broke, or "". `targets` the balls it may hit first, `group`
/// the shooter's (0: the table is open).
std::string eight_foul(const ShotFacts& f, const std::vector<int>& targets, int group) {
  if (f.first_hit < 0) return kMissed;
  if (!contains(targets, f.first_hit)) {
    std::string hit = "the cue ball hit " + the(f.first_hit) + " first";
    if (group == 0) return hit + " on an open table";
    return hit + ", not " + (contains(targets, 8) ? the(8) : group_one(group));
  }
  if (f.scratch) return kScratch;
  if (f.pocketed.empty() && !f.cushion_after_hit) return no_cushion(f.first_hit);
  return "";
}

/// 8-ball, a legal shot that did not make the 8: the ball that counts as called and made in its called
/// pocket (a call of ball -1 takes the first ball of the shooter's group made, in the pocket it went
/// into), or -1 (nothing called was made, or a safety).
int called_ball_made(const ShotFacts& f, const ShotCall& call, int group) {
  if (call.safety) return -1;
  auto allowed = [group](int ball) {
    return ball != 8 && group_of(ball) != 0 && (group == 0 || group_of(ball) == group);
  };
  for (std::size_t i = 0; i < f.pocketed.size(); ++i) {
    const int ball = f.pocketed[i];
    if (!allowed(ball)) continue;
    if (call.ball < 0) return ball;
    if (ball == call.ball) return call.pocket < 0 || f.pockets[i] == call.pocket ? ball : -1;
  }
  return -1;
}

TurnVerdict verdict_of(const ShotFacts& f, int shooter, bool break_shot) {
  TurnVerdict v;
  v.shooter = shooter;
  v.break_shot = break_shot;
  v.pocketed = f.pocketed;
  return v;
}

}  // namespace

ShotFacts shot_facts(const std::vector<Event>& events, const std::vector<PocketDrop>& drops,
                     const std::vector<Ball>& balls, int shot) {
  ShotFacts f;
  double start = kNever, end = kNever;
  shot_window(events, shot, start, end);
  if (start == kNever) return f;
  double hit_time = kNever;
  for (const Event& e : events) {
    if (e.shot != shot || e.type != EventType::ball_ball) continue;
    for (const Contact& c : contacts_of(e)) {
      const int a = painted(balls, c.a), b = painted(balls, c.b);
      if (a < 0 || b < 0 || (a == 0) == (b == 0) || c.time >= hit_time) continue;
      hit_time = c.time;
      f.first_hit = a == 0 ? b : a;
    }
  }
  std::set<int> cushioned;
  for (const Event& e : events) {
    if (e.shot != shot || (e.type != EventType::ball_rail && e.type != EventType::ball_jaw) || e.balls.empty())
      continue;
    const int ball = painted(balls, e.balls[0]);
    if (ball > 0) cushioned.insert(ball);
    if (ball >= 0 && e.time > hit_time) f.cushion_after_hit = true;
  }
  f.object_balls_to_cushion = static_cast<int>(cushioned.size());
  std::vector<PocketDrop> mine;
  for (const PocketDrop& d : drops)
    if (d.time >= start && d.time < end) mine.push_back(d);
  std::stable_sort(mine.begin(), mine.end(), [](const PocketDrop& x, const PocketDrop& y) { return x.time < y.time; });
  for (const PocketDrop& d : mine) {
    const int ball = painted(balls, d.ball);
    if (ball == 0 && !f.scratch) {
      f.scratch = true;
      f.scratch_pocket = d.pocket;
    } else if (ball > 0 && !contains(f.pocketed, ball)) {
      f.pocketed.push_back(ball);
      f.pockets.push_back(d.pocket);
    }
  }
  return f;
}

GameRules::GameRules(RackGame game, std::vector<int> object_balls) : game_(game), on_table_(std::move(object_balls)) {
  std::sort(on_table_.begin(), on_table_.end());
  on_table_.erase(std::unique(on_table_.begin(), on_table_.end()), on_table_.end());
  std::erase_if(on_table_, [](int ball) { return ball <= 0; });
  if (game_ == RackGame::eight_ball) {
    winning_ = 8;
  } else {
    // The 9 (the 10 in 10-ball); a scene's own set of balls without it: its highest ball.
    winning_ = game_ == RackGame::ten_ball ? 10 : 9;
    if (!contains(on_table_, winning_) && !on_table_.empty()) winning_ = on_table_.back();
  }
}

std::vector<int> GameRules::targets() const {
  if (on_table_.empty()) return {};
  if (game_ != RackGame::eight_ball) {
    return {on_table_.front()};  // a push-out may hit any ball, but a shot that is not one must hit the lowest
  }
  if (break_next_) return on_table_;
  const int group = group_[shooter_];
  std::vector<int> out;
  for (int ball : on_table_)
    if (ball != 8 && group_of(ball) != 0 && (group == 0 || group_of(ball) == group)) out.push_back(ball);
  if (out.empty() && contains(on_table_, 8)) out.push_back(8);
  return out;
}

ShotRules GameRules::next() const {
  ShotRules r;
  r.shooter = shooter_;
  r.break_shot = break_next_;
  r.in_hand = in_hand_;
  r.targets = targets();
  r.winning_ball = winning_;
  r.may_push_out = game_ != RackGame::eight_ball && push_out_next_;
  r.call_required = game_ == RackGame::eight_ball && !break_next_;
  return r;
}

TurnVerdict GameRules::judge(const ShotFacts& facts, const ShotCall& call) {
  if (winner_) {
    TurnVerdict v = verdict_of(facts, shooter_, false);
    v.winner = winner_;
    return v;
  }
  push_out_pending_ = false;
  return game_ == RackGame::eight_ball ? judge_eight(facts, call) : judge_rotation(facts, call);
}

bool GameRules::take_push_out(bool take) {
  if (!push_out_pending_) return false;
  push_out_pending_ = false;
  if (!take) shooter_ = 1 - shooter_;
  return !take;
}

TurnVerdict GameRules::judge_rotation(const ShotFacts& f, const ShotCall& call) {
  TurnVerdict v = verdict_of(f, shooter_, break_next_);
  const int lowest = on_table_.empty() ? -1 : on_table_.front();
  const bool push_out = push_out_next_ && call.push_out;
  const std::string foul = push_out ? (f.scratch ? kScratch : "") : rotation_foul(f, lowest, break_next_);
  const bool winning_down = contains(f.pocketed, winning_);
  for (int ball : f.pocketed) remove_ball(on_table_, ball);
  const bool was_break = break_next_;
  break_next_ = false;
  push_out_next_ = false;
  const int other = 1 - shooter_;
  std::string spot;
  if (winning_down && (!foul.empty() || push_out)) {
    add_ball(on_table_, winning_);
    v.spotted.push_back(winning_);
    spot = "; " + the(winning_) + " is spotted";
  }
  if (!foul.empty()) {
    v.legal = false;
    v.foul = foul;
    if (!was_break) ++fouls_[shooter_];  // a foul on the break does not count toward three in a row
    v.fouls_in_row = fouls_[shooter_];
    if (fouls_[shooter_] >= 3) {
      winner_ = other;
      v.winner = other;
      v.call = "foul: " + foul + "; third foul in a row: loses the game";
      return v;
    }
    v.in_hand = InHand::anywhere;
    v.call = "foul: " + foul + spot + "; ball in hand" + (fouls_[shooter_] == 2 ? "; second foul in a row" : "");
    shooter_ = other;
    in_hand_ = InHand::anywhere;
    return v;
  }
  fouls_[shooter_] = 0;
  in_hand_ = InHand::none;
  if (push_out) {
    v.push_out = true;
    v.call = "push-out" + spot;
    push_out_pending_ = true;
    shooter_ = other;  // the incoming player chooses (take_push_out)
    return v;
  }
  if (winning_down) {
    winner_ = shooter_;
    v.winner = shooter_;
    v.call = "wins the game";
    return v;
  }
  push_out_next_ = was_break;
  v.continues = !f.pocketed.empty();
  if (!v.continues) shooter_ = other;
  return v;
}

TurnVerdict GameRules::judge_eight_break(const ShotFacts& f) {
  TurnVerdict v = verdict_of(f, shooter_, true);
  break_next_ = false;
  for (int ball : f.pocketed) remove_ball(on_table_, ball);
  std::string spot;
  if (contains(f.pocketed, 8)) {
    add_ball(on_table_, 8);
    v.spotted.push_back(8);
    spot = "; the 8 is spotted";
  }
  const bool legal_break = !f.pocketed.empty() || f.object_balls_to_cushion >= 4;
  if (f.scratch || !legal_break) {
    v.legal = false;
    v.foul = f.scratch ? kScratch : kIllegalBreak;
    v.in_hand = f.scratch ? InHand::kitchen : InHand::none;
    v.call =
        "foul: " + v.foul + spot + (f.scratch ? "; ball in hand behind the head string" : "; the table as it lies");
    in_hand_ = v.in_hand;
    shooter_ = 1 - shooter_;
    return v;
  }
  in_hand_ = InHand::none;
  v.continues = !f.pocketed.empty();
  v.call = spot.empty() ? "" : spot.substr(2);
  if (!v.continues) shooter_ = 1 - shooter_;
  return v;
}

TurnVerdict GameRules::judge_eight(const ShotFacts& f, const ShotCall& call) {
  if (break_next_) return judge_eight_break(f);
  TurnVerdict v = verdict_of(f, shooter_, false);
  const int group = group_[shooter_];
  const std::vector<int> targets_now = targets();
  const std::string foul = eight_foul(f, targets_now, group);
  if (contains(f.pocketed, 8)) return eight_down(f, call, foul, std::move(v));
  for (int ball : f.pocketed) remove_ball(on_table_, ball);
  const int other = 1 - shooter_;
  if (!foul.empty()) {
    v.legal = false;
    v.foul = foul;
    v.in_hand = InHand::anywhere;
    v.call = "foul: " + foul + "; ball in hand";
    in_hand_ = InHand::anywhere;
    shooter_ = other;
    return v;
  }
  in_hand_ = InHand::none;
  const int made = called_ball_made(f, call, group);
  if (made >= 0 && group == 0) {
    group_[shooter_] = group_of(made);
    group_[other] = 3 - group_of(made);
    v.call = group_name(group_of(made));
  }
  v.continues = made >= 0;
  if (!v.continues) shooter_ = other;
  return v;
}

/// 8-ball: the 8 went down after the break. It wins only made legally, called, in the called pocket,
/// after the shooter's group was cleared; otherwise the shooter loses.
TurnVerdict GameRules::eight_down(const ShotFacts& f, const ShotCall& call, const std::string& foul, TurnVerdict v) {
  const int group = group_[shooter_];
  const bool on_the_8 =
      group != 0 && !std::any_of(on_table_.begin(), on_table_.end(), [group](int b) { return group_of(b) == group; });
  std::size_t at = 0;
  while (f.pocketed[at] != 8) ++at;
  for (int ball : f.pocketed) remove_ball(on_table_, ball);
  std::string loss;
  if (group == 0)
    loss = "the 8 went down on an open table";
  else if (!on_the_8)
    loss = "the 8 went down before the " + group_name(group) + " were cleared";
  else if (f.scratch)
    loss = "the cue ball went into a pocket with the 8";
  else if (!foul.empty())
    loss = "the 8 went down on a foul: " + foul;
  else if (call.safety || (call.ball >= 0 && call.ball != 8))
    loss = "the 8 went down without being called";
  else if (call.pocket >= 0 && f.pockets[at] != call.pocket)
    loss = "the 8 went into another pocket than the one called";
  const int other = 1 - shooter_;
  if (loss.empty()) {
    winner_ = shooter_;
    v.winner = shooter_;
    v.call = "wins the game";
    return v;
  }
  v.legal = false;
  v.foul = loss;
  winner_ = other;
  v.winner = other;
  v.call = loss + ": loses the game";
  return v;
}

}  // namespace bsim
