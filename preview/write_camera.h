#pragma once
// --write-camera FILE: the automatic director's camera script as scene text, to paste and edit.
#include <string>

namespace bsim {

struct Shot;

/// Writes the director's `camera ... endcamera` text for `shot` into `path` ("-": standard output),
/// in place atomically (written beside it and renamed). Returns the exit status; reports on stderr.
int run_write_camera(const std::string& path, const Shot& shot, bool quiet = false);

/// Writes `text` into `path` ("-": standard output), in place atomically, as --write-camera and
/// --write-scene do. Returns the exit status; reports on stderr ("wrote PATH" unless quiet).
int write_text_output(const std::string& path, const std::string& text, bool quiet);

}  // namespace bsim
