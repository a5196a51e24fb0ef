#pragma once
// Writing one camera description into a scene's text: replacing what an existing description does,
// or inserting a new description line in the camera block (adding a block when there is none). The
// rest of the text (comments, spacing, line ends, the other statements) is kept byte for byte.
#include <optional>
#include <string>
#include <string_view>

#include "scene.h"

namespace bsim {

/// A scene text with one description written into it.
struct CameraSplice {
  std::string text;       ///< the new text (empty when there is an error)
  std::size_t begin = 0;  ///< where the description starts in `text` (its `event`)
  std::size_t end = 0;    ///< and where its written part ends
  std::string error;      ///< why nothing could be written
};

/// Replaces what description `index` of `scene` (parsed from `text`) does after its windows (its
/// mode and its numbers) by `mode_text` ("hover 1 2 3 0 0 0"), keeping its key as written, its
/// windows and its comment.
CameraSplice replace_camera_mode(std::string_view text, const Scene& scene, std::size_t index,
                                 const std::string& mode_text);

/// Inserts the description `line` ("event hit 0 5 0.3 0 look 1 2 3 5") into the camera block of
/// `scene` (parsed from `text`): before description `before` when given, else at the end of the block,
/// indented like the description beside it; a text without a camera block gets one at its end. The
/// text's own line ends (\n or \r\n) are used.
CameraSplice insert_camera_description(std::string_view text, const Scene& scene, std::optional<std::size_t> before,
                                       const std::string& line);

}  // namespace bsim
