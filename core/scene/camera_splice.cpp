#include "camera_splice.h"

#include <algorithm>
#include <vector>

#include "camera_key_text.h"
#include "scene_lexer.h"

namespace bsim {

namespace {

std::size_t offset_of(std::string_view text, const Token& token) {
  return static_cast<std::size_t>(token.text.data() - text.data());
}

std::size_t token_end(std::string_view text, const Token& token) { return offset_of(text, token) + token.text.size(); }

std::size_t line_start(std::string_view text, std::size_t offset) {
  const std::size_t nl = offset == 0 ? std::string_view::npos : text.rfind('\n', offset - 1);
  return nl == std::string_view::npos ? 0 : nl + 1;
}

bool only_blanks(std::string_view text, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i)
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\r') return false;
  return true;
}

/// The spaces and tabs a line starts with.
std::string indent_of(std::string_view text, std::size_t offset) {
  const std::size_t start = line_start(text, offset);
  std::size_t end = start;
  while (end < text.size() && (text[end] == ' ' || text[end] == '\t')) ++end;
  return std::string(text.substr(start, end - start));
}

/// The tokens a key is written with (an event number: one).
std::size_t token_count(const CameraKey& key) {
  const std::string text = camera_key_text(key);
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.end(), ' '));
}

bool same_loc(const SourceLoc& a, const SourceLoc& b) { return a.line == b.line && a.column == b.column; }

/// The text's tokens, and where the scene's entities are among them.
struct SceneTokens {
  std::string_view text;
  LexedText lexed;

  std::optional<std::size_t> at(const SourceLoc& loc) const {
    for (std::size_t k = 0; k < lexed.tokens.size(); ++k)
      if (same_loc(lexed.tokens[k].loc, loc)) return k;
    return std::nullopt;
  }
  /// The last token of the description starting at token `first`: before the next `event` or `endcamera`.
  std::size_t description_end(std::size_t first) const {
    const std::vector<Token>& tokens = lexed.tokens;
    std::size_t last = first;
    while (last + 1 < tokens.size() && tokens[last + 1].text != "event" && tokens[last + 1].text != "endcamera") ++last;
    return last;
  }
  /// The `endcamera` closing the block that starts at the scene's `camera`, if any.
  std::optional<std::size_t> block_end(const Scene& scene) const {
    const std::optional<std::size_t> camera = scene.camera_loc.known() ? at(scene.camera_loc) : std::nullopt;
    if (camera)
      for (std::size_t k = *camera + 1; k < lexed.tokens.size(); ++k)
        if (lexed.tokens[k].text == "endcamera") return k;
    return std::nullopt;
  }
  std::size_t offset(std::size_t token) const { return offset_of(text, lexed.tokens[token]); }
};

std::string not_found(const CameraShot& shot) {
  return "cannot find the description on line " + std::to_string(shot.loc.line);
}

/// Inserts `line` before the token at `o` (a description's `event`): on a line of its own when that
/// token starts its line.
CameraSplice insert_before(std::string_view text, std::size_t o, const std::string& line, const std::string& nl) {
  CameraSplice s;
  s.text = std::string(text);
  const std::size_t start = line_start(text, o);
  if (only_blanks(text, start, o)) {
    s.text.insert(start, indent_of(text, o) + line + nl);
    s.begin = start + indent_of(text, o).size();
  } else {
    s.text.insert(o, line + nl);
    s.begin = o;
  }
  s.end = s.begin + line.size();
  return s;
}

/// Inserts `line` before the `endcamera` at token `e`, indented by `indent`.
CameraSplice insert_at_end(const SceneTokens& t, std::size_t e, const std::string& indent, const std::string& line,
                           const std::string& nl) {
  CameraSplice s;
  s.text = std::string(t.text);
  const std::size_t o = t.offset(e), start = line_start(t.text, o);
  if (only_blanks(t.text, start, o)) {
    s.text.insert(start, indent + line + nl);
    s.begin = start + indent.size();
  } else {
    // `camera endcamera` or a description and `endcamera` on one line: break the line there.
    const std::size_t p = token_end(t.text, t.lexed.tokens[e - 1]);
    s.text.replace(p, o - p, nl + indent + line + nl);
    s.begin = p + nl.size() + indent.size();
  }
  s.end = s.begin + line.size();
  return s;
}

}  // namespace

CameraSplice replace_camera_mode(std::string_view text, const Scene& scene, std::size_t index,
                                 const std::string& mode_text) {
  const SceneTokens t{text, lex_scene(text)};
  const CameraShot& shot = scene.camera[index];
  const std::optional<std::size_t> first = t.at(shot.loc);
  // After `event`, the key and the two windows.
  const std::size_t mode_token = first ? *first + 1 + token_count(shot.key) + 2 : t.lexed.tokens.size();
  CameraSplice s;
  if (!first || mode_token >= t.lexed.tokens.size()) {
    s.error = not_found(shot);
    return s;
  }
  const std::size_t from = t.offset(mode_token);
  const std::size_t to = token_end(text, t.lexed.tokens[t.description_end(*first)]);
  s.text = std::string(text);
  s.text.replace(from, to - from, mode_text);
  s.begin = t.offset(*first);
  s.end = from + mode_text.size();
  return s;
}

CameraSplice insert_camera_description(std::string_view text, const Scene& scene, std::optional<std::size_t> before,
                                       const std::string& line) {
  const SceneTokens t{text, lex_scene(text)};
  const std::string nl = text.find("\r\n") != std::string_view::npos ? "\r\n" : "\n";  // the file's line ends
  if (before) {
    const std::optional<std::size_t> first = t.at(scene.camera[*before].loc);
    if (!first) {
      CameraSplice s;
      s.error = not_found(scene.camera[*before]);
      return s;
    }
    return insert_before(text, t.offset(*first), line, nl);
  }
  if (const std::optional<std::size_t> end = t.block_end(scene)) {
    // Indented like the last description, or like `endcamera` in an empty block.
    std::string indent = indent_of(text, t.offset(*end));
    if (!scene.camera.empty())
      if (const auto last = t.at(scene.camera.back().loc)) indent = indent_of(text, t.offset(*last));
    return insert_at_end(t, *end, indent, line, nl);
  }
  // No camera block: one at the end of the text.
  CameraSplice s;
  s.text = std::string(text);
  if (!s.text.empty() && s.text.back() != '\n') s.text += nl;
  s.text += "camera" + nl;
  s.begin = s.text.size();
  s.text += line + nl + "endcamera" + nl;
  s.end = s.begin + line.size();
  return s;
}

}  // namespace bsim
