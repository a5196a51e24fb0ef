#pragma once
// Reading and writing whole files, shared by both programs: a scene file (so that both say the same thing
// about a scene they cannot read), the whole text of a log or progress file a child wrote, and a
// text file written whole or not at all.
#include <optional>
#include <string>
#include <string_view>

namespace bsim {

/// The whole text of the scene file at `path`, or nothing with `error` set to the line to print:
/// "PATH: error: is a directory, not a scene file" or
/// "PATH: error: cannot read the scene file: REASON" (REASON: the system's words, e.g. "Permission denied").
std::optional<std::string> read_scene_file(const std::string& path, std::string& error);

/// The whole content of the file at `path`; empty when it is missing or cannot be read (a child's
/// log or progress file that was never written reads as nothing to report).
std::string read_text_file(const std::string& path);

/// Writes `text` to `path` under a temporary name beside it, then renames it over `path`: a reader
/// never sees half a file, and a failed write leaves `path` as it was. False with `error` set
/// ("cannot write PATH: REASON") when it fails.
bool write_text_file(const std::string& path, std::string_view text, std::string& error);

}  // namespace bsim
