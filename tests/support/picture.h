#pragma once
// A PNG read back into memory for the tests that compare rendered pictures (stb_image).
#include <filesystem>
#include <vector>

namespace bsim::test {

/// An 8-bit RGB picture, rows from the top.
struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

/// The PNG at `path` as RGB; a test failure (REQUIRE) when it cannot be read.
Picture load_png(const std::filesystem::path& path);

}  // namespace bsim::test
