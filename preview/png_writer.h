#pragma once
// Writing what GL drew as a PNG: its RGBA rows, bottom row first, become the RGB rows, top row first,
// of the one PNG encoder both programs share (png_file.h).
#include <cstdint>
#include <string>
#include <vector>

namespace bsim {

/// RGBA pixels as GL reads them (bottom row first) to an RGB PNG at `path`. The file appears only
/// complete (atomic_file.h).
bool write_gl_png(const std::string& path, const std::vector<std::uint8_t>& rgba_bottom_up, int width, int height,
                  std::string& error);

}  // namespace bsim
