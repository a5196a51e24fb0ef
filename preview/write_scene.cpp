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

bool same_place(const SourceLoc& a, const SourceLoc& b) { return a.line == b.line && a.column == b.column; }

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
      if (c.aims() && same_place(token.loc, c.loc)) return &c;
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
    else if (t == "ball" && same_place(tokens[k].loc, struck.loc) && k + 7 < tokens.size())
      edits.push_back(span(k + 5, k + 7, numbers(struck.velocity)));  // after the number and the position
    else if (t == "spin" && k + 4 < tokens.size() && tokens[k + 1].text == std::to_string(first.target))
      edits.push_back(span(k + 2, k + 4, numbers(struck.spin)));
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string out(text);
  for (const Edit& e : edits) out.replace(e.begin, e.end - e.begin, e.with);
  return out;
}

int run_write_scene(const std::string& path, std::string_view text, const Shot& shot, bool quiet) {
  return write_text_output(path, scene_text_resolved(text, shot.scene), quiet);
}

}  // namespace bsim
