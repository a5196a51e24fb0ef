#pragma once
// An off-screen picture: an OSMesa GL context with Dear ImGui on top for text and 2D drawing.
#include <cstdint>
#include <string>
#include <vector>

#include "fonts.h"
#include "osmesa_context.h"

struct ImDrawList;
struct ImGuiContext;

namespace bsim {

class HeadlessCanvas {
 public:
  HeadlessCanvas() = default;
  ~HeadlessCanvas();
  HeadlessCanvas(const HeadlessCanvas&) = delete;
  HeadlessCanvas& operator=(const HeadlessCanvas&) = delete;

  /// Opens a width x height canvas whose body text is `text_px` high.
  bool open(int width, int height, float text_px, std::string& error);
  int width() const { return gl_.width(); }
  int height() const { return gl_.height(); }
  const UiFonts& fonts() const { return fonts_; }

  /// Starts the 2D layer; draw into the returned list, then call end_2d() to put it over the GL picture.
  ImDrawList* begin_2d();
  void end_2d();

  /// RGBA, bottom row first.
  const std::vector<std::uint8_t>& pixels() { return gl_.pixels(); }
  bool write_png(const std::string& path, std::string& error);

 private:
  OsmesaContext gl_;
  ImGuiContext* imgui_ = nullptr;
  bool backend_ = false;
  UiFonts fonts_;
};

}  // namespace bsim
