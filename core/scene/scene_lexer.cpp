#include "scene_lexer.h"

namespace bsim {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Long garbage (a binary file given by mistake) should not flood the terminal.
constexpr std::size_t kMaxQuotedBytes = 40;

}  // namespace

LexedText lex_scene(std::string_view text) {
  LexedText out;
  int line = 1, column = 1;
  std::size_t i = 0;
  // A byte-order mark some editors write is not part of the first token.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") {
    i = 3;
    column = 4;
  }
  out.end = {1, 1};
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      column = 1;
      ++i;
    } else if (is_space(c)) {
      ++column;
      ++i;
    } else if (c == '#') {
      out.comments.push_back({line, column});
      while (i < text.size() && text[i] != '\n') {
        ++i;
        ++column;
      }
    } else {
      const std::size_t start = i;
      const SourceLoc loc{line, column};
      while (i < text.size() && !is_space(text[i]) && text[i] != '#') {
        ++i;
        ++column;
      }
      out.tokens.push_back({text.substr(start, i - start), loc});
      out.end = {line, column};
    }
  }
  return out;
}

std::string quote_token(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "'";
  const bool cut = text.size() > kMaxQuotedBytes;
  for (unsigned char c : text.substr(0, kMaxQuotedBytes)) {
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out.push_back(static_cast<char>(c));
    } else {
      out.append("\\x").push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    }
  }
  if (cut) out.append("...");
  out.push_back('\'');
  return out;
}

}  // namespace bsim
