#pragma once
// A headless OpenGL 3.3 core context drawing into memory (Mesa's OSMesa on the llvmpipe rasteriser).
// libOSMesa is opened at run time so the same binary can also open a window through libGL.
#include <cstdint>
#include <string>
#include <vector>

namespace bsim {

class OsmesaContext {
 public:
  OsmesaContext() = default;
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  /// Creates the context and makes it current with a width x height RGBA buffer, and fills the GL table.
  bool open(int width, int height, std::string& error);
  int width() const { return width_; }
  int height() const { return height_; }
  /// Finishes drawing; the RGBA pixels, bottom row first.
  const std::vector<std::uint8_t>& pixels();

 private:
  void* context_ = nullptr;
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace bsim
