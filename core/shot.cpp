#include "shot.h"

#include <algorithm>

#include "camera_clearance.h"
#include "director.h"
#include "number_format.h"
#include "play.h"
#include "replay_camera.h"

namespace bsim {

FilmingNotes game_filming_notes(const Scene& scene, const GameRecord& record) {
  FilmingNotes notes;
  notes.opening = true;
  for (const GameTurn& turn : record.turns) {
    const auto k = static_cast<std::size_t>(turn.shot);
    if (k >= scene.cues.size()) continue;
    if (notes.subjects.size() <= k) notes.subjects.resize(k + 1, -1);
    const bool foul_without_pot = !turn.verdict.foul.empty() && turn.verdict.pocketed.empty();
    if (turn.planned.safety || foul_without_pot) notes.subjects[k] = scene.cues[k].target;
  }
  return notes;
}

namespace {

/// The game's winning shot and the ball that won it (the 10, 9 or 8 made on it; none when the game
/// was won on a foul); none when the game has no winner.
std::optional<ReplaySubject> winning_shot(const Scene& scene, const GameRecord& game) {
  if (!game.winner || game.turns.empty()) return std::nullopt;
  const GameTurn& turn = game.turns.back();
  const int game_ball = game.rules == RackGame::eight_ball ? 8 : game.rules == RackGame::ten_ball ? 10 : 9;
  ReplaySubject subject{turn.shot, -1};
  const auto& made = turn.verdict.pocketed;
  if (std::find(made.begin(), made.end(), game_ball) != made.end())
    for (int i = 0; i < static_cast<int>(scene.balls.size()); ++i)
      if (scene.ball(i).number == game_ball) subject.ball = i;
  return subject;
}

/// s a game's movie holds on a settled table (every ball stopped but for spin in place) before it
/// cuts to the next shot: long enough to see where the balls came to rest and the rules' call come up.
constexpr double kSettledHold = 0.8;
/// s it holds after the winning shot settles, before the replay: long enough to read WINNER.
constexpr double kWinnerHold = 1.5;
/// s: a shorter wait on spinning balls is not worth a cut.
constexpr double kShortestCut = 0.5;

}  // namespace

MovieTimeline broadcast_edit(const Timeline& timeline) {
  MovieTimeline movie;
  double from = 0;
  const int shots = timeline.shot_count();
  for (int k = 0; k < shots; ++k) {
    const bool last = k + 1 == shots;
    const double until = last ? timeline.duration() : timeline.shots()[static_cast<std::size_t>(k) + 1].start;
    const double held = timeline.settled(k) + (last ? kWinnerHold : kSettledHold);
    if (until - held < kShortestCut) continue;
    movie.add({from, held, 1.0, false});
    from = until;
  }
  if (from < timeline.duration() || movie.segments().empty()) movie.add({from, timeline.duration(), 1.0, false});
  return movie;
}

namespace {

/// The movie's frames: the simulation, or for a game with a winner that the director films, its
/// broadcast edit, then the winning shot again, slowed, from the replay's own camera.
void plan_movie(Shot& shot, ReplayChoice replay) {
  shot.movie = MovieTimeline(shot.timeline.duration());
  if (replay == ReplayChoice::off || !shot.game || !shot.camera) return;
  const std::optional<ReplaySubject> subject = winning_shot(shot.scene, *shot.game);
  if (!subject || subject->shot >= shot.timeline.shot_count()) return;
  const ReplayPlan plan = plan_replay(shot.scene, shot.timeline, *shot.camera, *subject);
  std::vector<Diagnostic> unused;  // the plan's descriptions fit the shot: they were built from it
  shot.replay_camera = CameraScript::build(shot.scene, plan.camera, shot.timeline, unused);
  if (!shot.replay_camera) return;
  shot.replay_what = plan.what;
  // The director's cuts fall where a shot ends; a camera script of the scene's own is shown whole.
  if (shot.directed) shot.movie = broadcast_edit(shot.timeline);
  shot.movie.add({plan.start, plan.end, kReplayRate, true});
}

}  // namespace

ShotResult load_shot(std::string_view text, std::string_view name, const ParseOptions& options, CameraChoice camera,
                     ReplayChoice replay) {
  ShotResult result;
  ParseResult parsed = parse_scene(text, name, options);
  result.diagnostics = std::move(parsed.diagnostics);
  if (!parsed.scene || has_errors(result.diagnostics)) return result;

  auto shot = std::make_unique<Shot>();
  shot->scene = std::move(*parsed.scene);
  // Every shot in turn from where the one before left the balls, each `cue I pot B P` at the heading
  // that pots B from there (play.h), or fail at the line to blame.
  std::optional<PlayFailure> failure;
  if (shot->scene.game) {
    // A game: its written shots, then the players', judged by the rules; filmed as the explicit scene.
    GameResult game = play_game(shot->scene);
    failure = std::move(game.failure);
    shot->scene = std::move(game.scene);
    shot->timeline = std::move(game.timeline);
    shot->game = std::move(game.record);
    if (shot->game->shot_limit) {
      const GameLine& line = *shot->scene.game;
      result.diagnostics.push_back({Severity::warning, line.shots_loc.known() ? line.shots_loc : line.loc,
                                    "the game stopped at its limit of " + std::to_string(line.shots) +
                                        " shots with no winner; give it more ('game ... shots N') to play it out"});
    }
  } else {
    PlayResult played = play(shot->scene);
    write_found(shot->scene, played.found);  // filmed as played: the headings found, the first ball as struck
    failure = std::move(played.failure);
    shot->timeline = std::move(played.timeline);
  }
  if (failure) {
    result.diagnostics.push_back({Severity::error, failure->loc, failure->message});
    return result;
  }
  // A game with no camera block of its own is filmed by the director, as a match is televised.
  if (camera == CameraChoice::automatic || (shot->game && shot->scene.camera.empty())) {
    shot->directed = direct_camera(shot->scene, shot->timeline,
                                   shot->game ? game_filming_notes(shot->scene, *shot->game) : FilmingNotes{});
    shot->scene.camera = shot->directed->shots;
  }
  shot->camera = CameraScript::build(shot->scene, shot->timeline, result.diagnostics);
  if (!shot->camera || has_errors(result.diagnostics)) shot->camera.reset();
  plan_movie(*shot, replay);
  if (shot->camera) {
    check_camera_clearance(shot->scene, shot->timeline, *shot->camera, result.diagnostics);
    // The stick keeps out of the movie's camera as it comes and goes, and out of the replay's too over
    // the stretch the replay films again.
    AlsoFilmed replayed;
    if (shot->replay_camera)
      for (const MovieSegment& segment : shot->movie.segments())
        if (segment.replay) replayed = {&*shot->replay_camera, segment.start, segment.end};
    shot->cue.emplace(shot->scene, shot->timeline, *shot->camera, replayed);
    // Each shot's stroke that no elevation clears: a warning at that shot's `stroke` line.
    for (const CueStroke& planned : shot->cue->strokes()) {
      const auto& stroke = shot->scene.cues[static_cast<std::size_t>(planned.shot)].stroke;
      if (stroke && !planned.clears)
        result.diagnostics.push_back(
            {Severity::warning, stroke->loc,
             "the stick raised " + format_number(stroke->elevation_deg) +
                 " degrees passes through a ball or a cushion on its stroke; no pose clears (raise it)"});
    }
  }
  result.shot = std::move(shot);
  return result;
}

}  // namespace bsim
