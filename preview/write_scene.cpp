#include "write_scene.h"

#include <algorithm>
#include <vector>

#include "number_format.h"
#include "scene_lexer.h"
#include "shot.h"
#include "write_camera.h"

namespace bsim {

namespace {

/// One replacement: bytes [begin, end) of the text become `with`.
struct Edit {
  std::size_t begin = 0, end = 0;
  std::string with;
};

bool same_line_column(const SourceLoc& a, const SourceLoc& b) { return a.line == b.line && a.column == b.column; }

std::string numbers(const Vec3& v) {
  return format_number(v.x()) + " " + format_number(v.y()) + " " + format_number(v.z());
}

}  // namespace

std::string scene_text_resolved(std::string_view text, const Scene& played) {
  if (std::none_of(played.cues.begin(), played.cues.end(), [](const Cue& c) { return c.aims(); }))
    return std::string(text);
  const LexedText lexed = lex_scene(text);
  const std::vector<Token>& tokens = lexed.tokens;
  const auto offset = [&](std::size_t k) { return static_cast<std::size_t>(tokens[k].text.data() - text.data()); };
  const auto span = [&](std::size_t first, std::size_t last, std::string with) {
    return Edit{offset(first), offset(last) + tokens[last].text.size(), std::move(with)};
  };
  // Each shot's `cue` line, found by where it is written; only the first shot can lack a stroke (its
  // ball and spin lines then carry what the heading gave the struck ball).
  const auto aimed_cue = [&](const Token& token) -> const Cue* {
    for (const Cue& c : played.cues)
      if (c.aims() && same_line_column(token.loc, c.loc)) return &c;
    return nullptr;
  };
  const Cue& first = played.cue();
  const bool first_resolves_balls = first.aims() && !first.stroke;
  const Ball& struck = played.ball(first.target);
  std::vector<Edit> edits;
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const std::string_view t = tokens[k].text;
    const Cue* cue = t == "cue" ? aimed_cue(tokens[k]) : nullptr;
    if (cue && k + 4 < tokens.size())
      edits.push_back(span(k + 2, k + 4, format_number(cue->heading_deg)));  // pot B P
    else if (!first_resolves_balls)
      continue;  // a stroke strikes the ball at the heading: its ball and spin lines stay as written
    else if (t == "ball" && same_line_column(tokens[k].loc, struck.loc) && k + 7 < tokens.size())
      edits.push_back(span(k + 5, k + 7, numbers(struck.velocity)));  // after the number and the position
    else if (t == "spin" && k + 4 < tokens.size() && tokens[k + 1].text == std::to_string(first.target))
      edits.push_back(span(k + 2, k + 4, numbers(struck.spin)));
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string out(text);
  for (const Edit& e : edits) out.replace(e.begin, e.end - e.begin, e.with);
  return out;
}

namespace {

/// The source text of the statements of `text` that start with one of `keep` (a camera description
/// whole), in file order, each ending its line.
std::string kept_statements(std::string_view text, std::initializer_list<std::string_view> keep) {
  const LexedText lexed = lex_scene(text);
  const std::vector<Token>& tokens = lexed.tokens;
  const auto offset = [&](std::size_t k) { return static_cast<std::size_t>(tokens[k].text.data() - text.data()); };
  constexpr std::string_view kStarts[] = {"cue",  "ball",   "rail",  "camera", "pocket", "spin",     "param",
                                          "rack", "stroke", "place", "game",   "player", "endcamera"};
  const auto starts = [&](std::string_view t) {
    return std::find(std::begin(kStarts), std::end(kStarts), t) != std::end(kStarts);
  };
  std::string out;
  for (std::size_t k = 0; k < tokens.size();) {
    std::size_t next = k + 1;
    if (tokens[k].text == "camera")
      while (next < tokens.size() && tokens[next - 1].text != "endcamera") ++next;
    else
      while (next < tokens.size() && !starts(tokens[next].text)) ++next;
    if (std::find(keep.begin(), keep.end(), tokens[k].text) != keep.end()) {
      const std::size_t last = next - 1;
      out.append(text.substr(offset(k), offset(last) + tokens[last].text.size() - offset(k))).append("\n");
    }
    k = next;
  }
  return out;
}

std::string place_line(const BallPlacement& p) {
  return "place " + std::to_string(p.ball) + " " + format_number(p.at->x()) + " " + format_number(p.at->y()) + "\n";
}

/// One played shot: its cue line with the heading and the call, its stroke, its places.
std::string cue_lines(const Cue& cue) {
  std::string out = "cue " + std::to_string(cue.target) + " " + format_number(cue.heading_deg);
  if (cue.call_safety)
    out += " call safety";
  else if (cue.call_push_out)
    out += " call push-out";
  else if (cue.aims())
    out += " call " + std::to_string(cue.pot_ball) + " " + std::to_string(cue.pot_pocket);
  else if (cue.call_ball >= 0)
    out += " call " + std::to_string(cue.call_ball) + " " + std::to_string(cue.call_pocket);
  out += "\n";
  if (cue.stroke)
    out += "stroke " + format_number(cue.stroke->speed) + " " + format_number(cue.stroke->side) + " " +
           format_number(cue.stroke->height) + " " + format_number(cue.stroke->elevation_deg) + "\n";
  for (const BallPlacement& p : cue.places)
    if (p.at) out += place_line(p);
  return out;
}

}  // namespace

std::string game_scene_text(std::string_view text, const Shot& shot) {
  const Scene& scene = shot.scene;
  const GameLine& game = *scene.game;
  std::string out = "# " + scene.name + ": the game as played, shot by shot\n";
  out += kept_statements(text, {"param", "rail", "pocket"});
  out += "game " + std::string(rack_game_name(game.rules)) + " seed " + std::to_string(game.seed) + " shots " +
         std::to_string(game.shots) + "\n";
  for (const PlayerLine& p : game.players) out += "player " + p.name + " noise " + format_number(p.noise) + "\n";
  for (const Ball& b : scene.balls) {
    const Quat& q = b.orientation;
    out += "ball " + std::to_string(b.number) + " " + numbers(b.position) + " 0 0 0 " + format_number(q.w()) + " " +
           format_number(q.x()) + " " + format_number(q.y()) + " " + format_number(q.z()) + "\n";
  }
  for (std::size_t k = 0; k < scene.cues.size(); ++k) {
    Cue cue = scene.cues[k];
    if (shot.game && k < shot.game->turns.size() && !shot.game->turns[k].written) {
      // The player's call, so the rules judge the shot as they judged it in play.
      const ShotCall& call = shot.game->turns[k].planned;
      cue.call_safety = call.safety;
      cue.call_push_out = call.push_out;
      cue.call_ball = -1;
      for (std::size_t i = 0; i < scene.balls.size() && call.ball >= 0; ++i)
        if (scene.balls[i].number == call.ball) cue.call_ball = static_cast<int>(i);
      cue.call_pocket = call.pocket;
    }
    out += cue_lines(cue);
  }
  return out + kept_statements(text, {"camera"});
}

int run_write_scene(const std::string& path, std::string_view text, const Shot& shot, bool quiet) {
  return write_text_output(path, shot.game ? game_scene_text(text, shot) : scene_text_resolved(text, shot.scene),
                           quiet);
}

}  // namespace bsim
