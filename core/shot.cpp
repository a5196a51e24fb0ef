#include "shot.h"

#include "camera_clearance.h"
#include "director.h"
#include "number_format.h"
#include "play.h"

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

ShotResult load_shot(std::string_view text, std::string_view name, const ParseOptions& options, CameraChoice camera) {
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
    shot->directed = direct_camera(shot->scene, shot->timeline, shot->game ? game_filming_notes(shot->scene, *shot->game)
                                                                           : FilmingNotes{});
    shot->scene.camera = shot->directed->shots;
  }
  shot->camera = CameraScript::build(shot->scene, shot->timeline, result.diagnostics);
  if (!shot->camera || has_errors(result.diagnostics)) {
    shot->camera.reset();
  } else {
    check_camera_clearance(shot->scene, shot->timeline, *shot->camera, result.diagnostics);
    shot->cue.emplace(shot->scene, shot->timeline, *shot->camera);
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
