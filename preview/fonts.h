#pragma once
// Text for pictures and the window: DejaVu (Debian's fonts-dejavu-core) when present, else ImGui's own font.
#include <string>

#include "dejavu.h"

struct ImFont;
struct ImFontAtlas;

namespace bsim {

struct UiFonts {
  ImFont* regular = nullptr;
  ImFont* small = nullptr;
  ImFont* bold = nullptr;
  float regular_size = 13;  ///< px
  float small_size = 13;
  float bold_size = 13;
};

/// Adds the three faces to `atlas`, sized for a picture whose body text is `size` pixels high.
UiFonts add_ui_fonts(ImFontAtlas& atlas, float size);

}  // namespace bsim
