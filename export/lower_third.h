#pragma once
// A game movie's caption drawn on a developed frame as television draws a lower third: a dark,
// semi-transparent panel low in one corner with the two players (the one at the table marked with
// the accent colour), the game and the shot, a row of small discs in the balls' colours (a stripe
// drawn as a stripe, a ball made only its faint ring), and above it the referee's calls, each a
// coloured tag and its words, and a REPLAY tag on the replay's frames. Everything is measured in
// pixels of a 720-line picture and scales with the height (a little less steeply below 720 lines, so
// that the text stays legible at 640x360); nothing reaches the upper half.
//
// The text is DejaVu Sans (Debian's fonts-dejavu-core) rasterised with stb_truetype. Everything is
// integer or basic IEEE arithmetic (no libm call whose last bit may differ between CPUs), so a frame
// is the same bytes on every machine with the same fonts; the fonts' bytes are part of
// lower_third_signature(), and so of every captioned frame's key in the frame store.
#include <cstdint>
#include <string>
#include <vector>

#include "caption.h"

namespace bsim {

/// A caption as a frame shows it: what it says and the lower corner it is in.
struct FrameCaption {
  Caption caption;
  bool right = false;  ///< the lower right corner; else the lower left
  bool operator==(const FrameCaption&) const = default;
};

/// Columns x0 to x1 - 1 and rows y0 to y1 - 1 of a picture.
struct CaptionBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// The part of a width x height picture a caption of a rack of `rack_size` balls may cover in the
/// corner given: its column, from the middle of the picture down to the bottom edge.
CaptionBox lower_third_column(int rack_size, int width, int height, bool right);

/// A text that changes whenever the lower third's drawing would: its version and the fonts' bytes
/// (empty fonts' part when they are not installed).
std::string lower_third_signature();

/// Whether the fonts the captions need are installed; else false with `error` saying what to do.
bool lower_third_fonts(std::string& error);

/// Draws `caption` over `srgb` (8-bit sRGB, three bytes a pixel, rows from the top), width x height.
/// False with `error` when the fonts are not installed.
bool draw_lower_third(std::vector<std::uint8_t>& srgb, int width, int height, const FrameCaption& caption,
                      std::string& error);

}  // namespace bsim
