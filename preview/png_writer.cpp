#include "png_writer.h"

#include "png_file.h"

namespace bsim {

bool write_gl_png(const std::string& path, const std::vector<std::uint8_t>& rgba, int width, int height,
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
  return write_png(path, rgb, width, height, error);
}

}  // namespace bsim
