#pragma once
// Writing RGB PNGs with stb, fast (compression level 1), into place atomically.
#include <cstdint>
#include <string>
#include <vector>

namespace bsim {

/// RGBA pixels as GL reads them (bottom row first) to an RGB PNG at `path`. The file appears only
/// complete: it is written beside `path` and renamed.
bool write_png(const std::string& path, const std::vector<std::uint8_t>& rgba_bottom_up, int width, int height,
               std::string& error);

}  // namespace bsim
