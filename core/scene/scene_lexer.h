#pragma once
// Scene text -> tokens with their line and column. Tokens are separated by whitespace; `#` starts a
// comment to the end of the line (an extension, so the lexer records where each one starts).
#include <string>
#include <string_view>
#include <vector>

#include "source_loc.h"

namespace bsim {

struct Token {
  std::string_view text;  ///< a view into the scene text
  SourceLoc loc;          ///< where its first byte is
};

struct LexedText {
  std::vector<Token> tokens;
  std::vector<SourceLoc> comments;  ///< the `#` of every comment
  SourceLoc end;                    ///< just past the last token (1:1 for a file without tokens)
};

LexedText lex_scene(std::string_view text);

/// The token as it should appear in a message: quoted, non-printable bytes escaped, long ones cut.
std::string quote_token(std::string_view text);

}  // namespace bsim
