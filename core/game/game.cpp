#include "game.h"

#include <algorithm>
#include <ctime>

#include "player.h"

namespace bsim {

namespace {

/// The file-order index of the ball painted `number`, or -1.
int index_of(const std::vector<Ball>& balls, int number) {
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (balls[i].number == number) return static_cast<int>(i);
  return -1;
}

/// A game's players: the `player` lines', then defaults.
std::vector<PlayerSkill> skills(const GameLine& game) {
  std::vector<PlayerSkill> out;
  const std::vector<std::string> names = player_names(game);
  for (std::size_t p = 0; p < 2; ++p) out.push_back({names[p], p < game.players.size() ? game.players[p].noise : 1.0});
  return out;
}

/// A written `cue` line's call: its `pot B P`, or none.
ShotCall written_call(const Scene& scene, const Cue& cue) {
  ShotCall call;
  call.safety = cue.call_safety;
  call.push_out = cue.call_push_out;
  const int ball = cue.aims() ? cue.pot_ball : cue.call_ball;
  if (ball >= 0) {
    call.ball = scene.ball(ball).number;
    call.pocket = cue.aims() ? cue.pot_pocket : cue.call_pocket;
  }
  return call;
}

/// One game in play: the explicit scene growing a shot at a time, the chain that plays it, the rules.
class Match {
 public:
  explicit Match(const Scene& scene)
      : written_(scene),
        line_(*scene.game),
        players_(skills(line_)),
        rules_(line_.rules, object_balls(scene.balls)),
        noise_(line_.seed ^ 0x6A09E667F3BCC908ull) {
    result_.scene = scene;
    result_.scene.cues.clear();
    result_.record.rules = line_.rules;
    for (const PlayerSkill& p : players_) {
      result_.record.players.push_back(p.name);
      result_.record.noise.push_back(p.noise);
    }
    cue_ball_ = index_of(scene.balls, 0);
  }

  GameResult run() {
    // The written shots are all played, even past the limit; the players stop at it.
    const int limit = std::max(line_.shots, written_.shot_count());
    for (int k = 0; k < limit && !rules_.over(); ++k)
      if (!shot(k)) break;
    result_.record.winner = rules_.winner();
    result_.record.shot_limit =
        !rules_.over() && !result_.failure && limit == static_cast<int>(result_.record.turns.size());
    result_.timeline = chain_ ? chain_->finish() : Timeline();
    if (chain_) write_found(result_.scene, chain_->found());  // a written `pot` shot at the heading found
    return std::move(result_);
  }

 private:
  static std::vector<int> object_balls(const std::vector<Ball>& balls) {
    std::vector<int> out;
    for (const Ball& b : balls)
      if (b.number > 0) out.push_back(b.number);
    return out;
  }

  /// Plays shot k; false when it could not be played (the failure is kept).
  bool shot(int k) {
    const ShotRules next = rules_.next();
    GameTurn turn;
    turn.shot = k;
    turn.player = next.shooter;
    Cue cue;
    if (k < written_.shot_count()) {
      cue = written_.cues[static_cast<std::size_t>(k)];
      turn.written = true;
      turn.planned = written_call(written_, cue);
    } else {
      cue = planned_cue(k, next, turn);
    }
    cue.places.insert(cue.places.begin(), spotted_.begin(), spotted_.end());
    spotted_.clear();
    result_.scene.cues.push_back(cue);
    if (!chain_) chain_.emplace(result_.scene);
    if (auto failure = chain_->play(result_.scene, k)) {
      result_.failure = std::move(failure);
      return false;
    }
    const ShotFacts facts = shot_facts(chain_->events(), chain_->drops(), result_.scene.balls, k);
    turn.verdict = rules_.judge(facts, turn.planned);
    if (turn.verdict.push_out) answer_push_out(k, turn.verdict);
    spot(turn.verdict.spotted);
    turn.on_table = rules_.on_table();
    result_.record.turns.push_back(std::move(turn));
    return true;
  }

  /// The table as the next shooter finds it: the balls at rest, the rules' spotted balls on their spots.
  Scene table() const {
    Scene t = result_.scene;
    t.cues.clear();
    if (chain_) t.balls = chain_->standing();
    for (const BallPlacement& p : spotted_) {
      Ball& b = t.balls[static_cast<std::size_t>(p.ball)];
      b.position = *p.at;
      b.pocket = -1;
    }
    return t;
  }

  std::uint64_t plan_seed(int k) const {
    SplitMix64 mix(line_.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(k));
    return mix.next();
  }

  /// The shooter's plan for shot k, as the arm delivers it (noise), with the cue ball placed by hand.
  Cue planned_cue(int k, const ShotRules& next, GameTurn& turn) {
    const PlayerSkill& skill = players_[static_cast<std::size_t>(next.shooter)];
    const std::clock_t begun = std::clock();
    const PlannedShot plan = plan_shot(table(), next, skill, plan_seed(k));
    turn.planning_seconds = static_cast<double>(std::clock() - begun) / CLOCKS_PER_SEC;
    turn.planned = plan.call;
    turn.chance = plan.chance;
    turn.simulations = plan.simulations;
    Cue cue;
    cue.target = cue_ball_;
    cue.heading_deg = plan.heading_deg;
    cue.stroke = plan.stroke;
    apply_noise(skill.noise, result_.scene.physics.ball_radius, noise_, cue.heading_deg, *cue.stroke);
    if (plan.place && next.in_hand != InHand::none) {
      if (k == 0) {
        result_.scene.balls[static_cast<std::size_t>(cue_ball_)].position = *plan.place;
      } else {
        BallPlacement place;
        place.ball = cue_ball_;
        place.at = *plan.place;
        cue.places.push_back(place);
      }
    }
    return cue;
  }

  /// After a push-out the incoming player takes the table or hands it back.
  void answer_push_out(int k, TurnVerdict& verdict) {
    const ShotRules offered = rules_.next();
    const PlayerSkill& taker = players_[static_cast<std::size_t>(offered.shooter)];
    const bool take = take_push_out(table(), offered, taker, plan_seed(k) ^ 0x5DEECE66Dull);
    verdict.continues = rules_.take_push_out(take);
  }

  /// The rules' spotted balls, put on the foot spot (or behind it on the long axis) before the next shot.
  void spot(const std::vector<int>& numbers) {
    if (numbers.empty()) return;
    std::vector<Ball> balls = chain_->standing();
    for (int number : numbers) {
      const int i = index_of(balls, number);
      if (i < 0) continue;
      const Vec3 at = spot_place(result_.scene, balls, i, kFootSpotX, +1);
      balls[static_cast<std::size_t>(i)].position = at;
      balls[static_cast<std::size_t>(i)].pocket = -1;
      BallPlacement place;
      place.ball = i;
      place.at = at;
      spotted_.push_back(place);
    }
  }

  const Scene& written_;
  const GameLine& line_;
  std::vector<PlayerSkill> players_;
  GameRules rules_;
  SplitMix64 noise_;
  int cue_ball_ = 0;
  GameResult result_;
  std::optional<ShotChain> chain_;
  std::vector<BallPlacement> spotted_;  ///< the rules' spotted balls, placed before the next shot
};

}  // namespace

std::vector<std::string> player_names(const GameLine& game) {
  std::vector<std::string> names = {"Player 1", "Player 2"};
  for (std::size_t p = 0; p < game.players.size() && p < 2; ++p) names[p] = game.players[p].name;
  return names;
}

GameResult play_game(const Scene& scene) {
  BSIM_EXPECT(scene.game.has_value(), "a game needs a game line");
  return Match(scene).run();
}

}  // namespace bsim
