#pragma once
// Reading a scene file from disk, shared by both programs so that they say the same thing about a
// scene they cannot read.
#include <optional>
#include <string>

namespace bsim {

/// The whole text of the scene file at `path`, or nothing with `error` set to the line to print:
/// "PATH: error: is a directory, not a scene file" or
/// "PATH: error: cannot read the scene file: REASON" (REASON: the system's words, e.g. "Permission denied").
std::optional<std::string> read_scene_file(const std::string& path, std::string& error);

}  // namespace bsim
