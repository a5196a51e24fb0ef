#include "png_writer.h"

#include <cstdio>
#include <filesystem>

#include <stb_image_write.h>

namespace bsim {

bool write_png(const std::string& path, const std::vector<std::uint8_t>& rgba, int width, int height,
               std::string& error) {
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  std::vector<std::uint8_t> rgb(w * h * 3);
  for (std::size_t y = 0; y < h; ++y) {
    const std::uint8_t* src = rgba.data() + (h - 1 - y) * w * 4;
    std::uint8_t* dst = rgb.data() + y * w * 3;
    for (std::size_t x = 0; x < w; ++x) {
      dst[3 * x] = src[4 * x];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
  // Level 1 with filters still chosen per row: about three times faster than the default, files ~20% larger.
  stbi_write_png_compression_level = 1;
  const std::filesystem::path target(path);
  const std::filesystem::path temporary = target.string() + ".partial";
  if (!stbi_write_png(temporary.c_str(), width, height, 3, rgb.data(), width * 3)) {
    error = "cannot write " + path;
    std::remove(temporary.c_str());
    return false;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    error = "cannot write " + path + ": " + ec.message();
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace bsim
