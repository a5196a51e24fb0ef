#pragma once
// --write-camera FILE: the automatic director's camera script as scene text, to paste and edit.
#include <string>

namespace bsim {

struct Shot;

/// Writes the director's `camera ... endcamera` text for `shot` into `path` ("-": standard output),
/// in place atomically (written beside it and renamed). Returns the exit status; reports on stderr.
int run_write_camera(const std::string& path, const Shot& shot, bool quiet = false);

}  // namespace bsim
