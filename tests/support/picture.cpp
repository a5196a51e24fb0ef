#include "picture.h"

#include <doctest/doctest.h>
#include <stb_image.h>

namespace bsim::test {

Picture load_png(const std::filesystem::path& path) {
  Picture p;
  int channels = 0;
  unsigned char* data = stbi_load(path.string().c_str(), &p.width, &p.height, &channels, 3);
  REQUIRE_MESSAGE(data != nullptr, "cannot read " << path.string());
  p.rgb.assign(data, data + 3 * static_cast<std::size_t>(p.width) * p.height);
  stbi_image_free(data);
  return p;
}

}  // namespace bsim::test
