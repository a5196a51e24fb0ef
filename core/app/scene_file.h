#pragma once
// Reading whole files, shared by both programs: a scene file (so that both say the same thing about a
// scene they cannot read) and the whole text of a log or progress file a child wrote. Files are
// written with atomic_file.h.
#include <optional>
#include <string>

namespace bsim {

/// The whole text of the scene file at `path`, or nothing with `error` set to the line to print:
/// "PATH: error: is a directory, not a scene file" or
/// "PATH: error: cannot read the scene file: REASON" (REASON: the system's words, e.g. "Permission denied").
std::optional<std::string> read_scene_file(const std::string& path, std::string& error);

/// The whole content of the file at `path`; empty when it is missing or cannot be read (a child's
/// log or progress file that was never written reads as nothing to report).
std::string read_text_file(const std::string& path);

}  // namespace bsim
