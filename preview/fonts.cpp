#include "fonts.h"

#include <imgui.h>

namespace bsim {

UiFonts add_ui_fonts(ImFontAtlas& atlas, float size) {
  UiFonts fonts;
  const std::string regular = find_dejavu("DejaVuSans.ttf");
  const std::string bold = find_dejavu("DejaVuSans-Bold.ttf");
  ImFontConfig config;
  config.OversampleH = 2;
  config.OversampleV = 1;
  // Latin plus the arrows and dots the labels use.
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x2013, 0x2014, 0x2022, 0x2022, 0x2026,
                                    0x2026, 0x2190, 0x2193, 0x25B2, 0x25BC, 0};
  const auto add = [&](const std::string& path, float px) -> ImFont* {
    if (!path.empty()) return atlas.AddFontFromFileTTF(path.c_str(), px, &config, kRanges);
    ImFontConfig fallback;
    fallback.SizePixels = 13;
    return atlas.AddFontDefault(&fallback);
  };
  fonts.regular = add(regular, size);
  fonts.small = add(regular, size * 0.85f);
  fonts.bold = add(bold, size * 1.25f);
  const bool dejavu = !regular.empty();
  fonts.regular_size = dejavu ? size : 13;
  fonts.small_size = dejavu ? size * 0.85f : 13;
  fonts.bold_size = dejavu && !bold.empty() ? size * 1.25f : 13;
  return fonts;
}

}  // namespace bsim
