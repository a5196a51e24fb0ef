#pragma once
// Reading whole files, shared by both programs: a scene (a file or the built-in break, so that both
// name it and say the same thing about a scene they cannot read) and the whole text of a log or
// progress file a child wrote. Files are written with atomic_file.h.
#include <optional>
#include <string>

namespace bsim {

/// Where a scene comes from: a file, or the built-in break when no path is given.
struct SceneOrigin {
  std::optional<std::string> path;  ///< none: the built-in break
  std::string shown_path;           ///< how diagnostics name it: the path, or "<built-in break.scn>"
  std::string name;                 ///< Scene::name: the file's stem, or the built-in break's name
};

/// The origin of the scene at `path`, or of the built-in break when there is none.
SceneOrigin scene_origin(const std::optional<std::string>& path);

/// The scene's text: the file's (as read_scene_file reads it, with its errors) or the built-in break's.
std::optional<std::string> read_scene_text(const SceneOrigin& origin, std::string& error);

/// The whole text of the scene file at `path`, or nothing with `error` set to the line to print:
/// "PATH: error: is a directory, not a scene file" or
/// "PATH: error: cannot read the scene file: REASON" (REASON: the system's words, e.g. "Permission denied").
std::optional<std::string> read_scene_file(const std::string& path, std::string& error);

/// The whole content of the file at `path`; empty when it is missing or cannot be read (a child's
/// log or progress file that was never written reads as nothing to report).
std::string read_text_file(const std::string& path);

}  // namespace bsim
