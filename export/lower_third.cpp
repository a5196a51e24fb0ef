#include "lower_third.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string_view>

#include "ball_look.h"
#include "dejavu.h"
#include "frame_cache.h"

// stb_truetype's rasteriser uses only basic arithmetic, floor, ceil and sqrt (all exact in IEEE);
// pow, cos, acos and fmod serve its signed distance fields alone, which the captions never draw.
namespace bsim::stbtt_unused {
[[noreturn]] inline double trap() {
  std::fprintf(stderr, "billiards-export: internal error: a font routine that is never used was called\n");
  std::abort();
}
}  // namespace bsim::stbtt_unused
#define STBTT_pow(x, y) ((void)(x), (void)(y), bsim::stbtt_unused::trap())
#define STBTT_cos(x) ((void)(x), bsim::stbtt_unused::trap())
#define STBTT_acos(x) ((void)(x), bsim::stbtt_unused::trap())
#define STBTT_fmod(x, y) ((void)(x), (void)(y), bsim::stbtt_unused::trap())
#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>

namespace bsim {

namespace {

/// Bumped whenever the drawing changes what it makes of the same caption.
constexpr const char* kLowerThirdVersion = "lower third 2";

/// The layout, in pixels of a 720-line picture (scaled with the height).
constexpr double kReferenceHeight = 720.0;
constexpr double kMarginX = 64, kMarginBottom = 40;  // inside the title-safe area
/// The panel's width: the least, about a quarter of a 16:9 picture (at 640x360, where everything is
/// drawn larger, 37 %), so that a ball in the middle of the picture (a shooter's view puts the cue ball
/// there, low) is clear of the panel in either corner.
constexpr double kPanelMinWidth = 340, kPad = 14;
constexpr double kNameRow = 34, kNameSize = 22, kSmallSize = 14, kAccentBar = 6;
constexpr double kBallRow = 38, kDisc = 24, kDiscStep = 30;
/// A rack of more than kFullRack balls (8-ball's 15) is drawn in smaller discs, closer together.
constexpr int kFullRack = 10;
constexpr double kSmallDisc = 18, kSmallDiscStep = 21;
constexpr double kStrip = 30, kStripLine = 22, kCallSize = 18, kTagPad = 10, kGap = 5;
constexpr int kMostCallLines = 2;

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};
constexpr Rgb kPanel{12, 18, 32}, kRowLit{36, 48, 76}, kWhite{255, 255, 255}, kDim{178, 186, 202},
    kSmallText{138, 150, 172}, kAccent{255, 190, 20}, kFoulTag{204, 26, 34}, kInfoTag{28, 108, 196},
    kStoppedTag{104, 108, 120}, kDark{14, 16, 22}, kReplayTag{204, 26, 34};
constexpr int kPanelAlpha = 204, kRowAlpha = 224;

struct Face {
  std::string bytes;
  stbtt_fontinfo info{};
  bool ok = false;
};

struct Fonts {
  Face regular, bold;
  std::string signature;  ///< the files' names and a hash of their bytes
};

bool load(const char* file, Face& face, std::string& signature) {
  const std::string path = find_dejavu(file);
  std::ifstream in(path, std::ios::binary);
  if (path.empty() || !in) return false;
  face.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const auto* data = reinterpret_cast<const unsigned char*>(face.bytes.data());
  face.ok = stbtt_InitFont(&face.info, data, stbtt_GetFontOffsetForIndex(data, 0)) != 0;
  char hash[32];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(face.bytes)));
  signature += std::string(" ") + file + ":" + hash;
  return face.ok;
}

const Fonts& fonts() {
  static const Fonts loaded = [] {
    Fonts f;
    const bool regular = load("DejaVuSans.ttf", f.regular, f.signature);  // both loaded: both in the signature
    const bool bold = load("DejaVuSans-Bold.ttf", f.bold, f.signature);
    if (!regular || !bold) f.regular.ok = f.bold.ok = false;
    return f;
  }();
  return loaded;
}

int round_px(double v) { return static_cast<int>(std::floor(v + 0.5)); }

/// The rack's row: each disc's diameter and the step from one to the next, in layout pixels.
std::pair<double, double> disc_layout(std::size_t rack_size) {
  return rack_size > kFullRack ? std::pair{kSmallDisc, kSmallDiscStep} : std::pair{kDisc, kDiscStep};
}

/// Pixels of the picture to one of the layout's: the height over 720, and up to 1.4 times that for
/// pictures of 360 lines or fewer, whose text would be too small to read at the same share.
double layout_scale(int height) {
  const double smaller = std::clamp((kReferenceHeight - height) / (0.5 * kReferenceHeight), 0.0, 1.0);
  return height / kReferenceHeight * (1.0 + 0.4 * smaller);
}

/// The picture being drawn on: blends colours over its pixels, clipped to it.
class Canvas {
 public:
  Canvas(std::vector<std::uint8_t>& srgb, int width, int height) : px_(srgb), width_(width), height_(height) {}
  int height() const { return height_; }

  /// Lays `color` over pixel (x, y) with opacity alpha / 255.
  void blend(int x, int y, Rgb color, int alpha) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0) return;
    alpha = std::min(alpha, 255);
    std::uint8_t* p = px_.data() + 3 * (static_cast<std::size_t>(y) * width_ + x);
    const int c[3] = {color.r, color.g, color.b};
    for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((p[k] * (255 - alpha) + c[k] * alpha + 127) / 255);
  }
  void fill(double x0, double y0, double x1, double y1, Rgb color, int alpha) {
    for (int y = round_px(y0); y < round_px(y1); ++y)
      for (int x = round_px(x0); x < round_px(x1); ++x) blend(x, y, color, alpha);
  }

 private:
  std::vector<std::uint8_t>& px_;
  int width_, height_;
};

/// The next code point of UTF-8 text at `at` (a byte that starts no sequence reads as itself).
int next_code_point(std::string_view text, std::size_t& at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at++);
  const int extra = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
  if (extra == 0 || at + extra > text.size()) return lead;
  int code = lead & (0x3F >> extra);
  for (int i = 0; i < extra; ++i) code = code << 6 | (byte(at++) & 0x3F);
  return code;
}

/// Width in pixels of `text` set in `face` at `size` pixels (ascent to descent).
double text_width(const Face& face, double size, std::string_view text) {
  const float scale = stbtt_ScaleForPixelHeight(&face.info, static_cast<float>(size));
  double pen = 0;
  int previous = 0;
  for (std::size_t at = 0; at < text.size();) {
    const int code = next_code_point(text, at);
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&face.info, code, &advance, &bearing);
    if (previous) pen += scale * stbtt_GetCodepointKernAdvance(&face.info, previous, code);
    pen += scale * advance;
    previous = code;
  }
  return pen;
}

/// Sets `text` with its left end at x and its letters standing on the line at `baseline`.
void draw_text(Canvas& canvas, const Face& face, double size, double x, double baseline, std::string_view text,
               Rgb color) {
  const float scale = stbtt_ScaleForPixelHeight(&face.info, static_cast<float>(size));
  const int line = round_px(baseline);
  double pen = x;
  int previous = 0;
  std::vector<unsigned char> glyph;
  for (std::size_t at = 0; at < text.size();) {
    const int code = next_code_point(text, at);
    if (previous) pen += scale * stbtt_GetCodepointKernAdvance(&face.info, previous, code);
    previous = code;
    const int left = static_cast<int>(std::floor(pen));
    const auto shift = static_cast<float>(pen - left);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&face.info, code, scale, scale, shift, 0, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      glyph.assign(static_cast<std::size_t>(w) * h, 0);
      stbtt_MakeCodepointBitmapSubpixel(&face.info, glyph.data(), w, h, w, scale, scale, shift, 0, code);
      for (int gy = 0; gy < h; ++gy)
        for (int gx = 0; gx < w; ++gx)
          canvas.blend(left + x0 + gx, line + y0 + gy, color, glyph[static_cast<std::size_t>(gy) * w + gx]);
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&face.info, code, &advance, &bearing);
    pen += scale * advance;
  }
}

/// The baseline that centres a line of `face` at `size` on `middle` (its caps' middle).
double centred_baseline(const Face& face, double size, double middle) {
  const float scale = stbtt_ScaleForPixelHeight(&face.info, static_cast<float>(size));
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  stbtt_GetCodepointBox(&face.info, 'H', &x0, &y0, &x1, &y1);
  return middle + 0.5 * scale * y1;
}

/// A disc of radius r at (cx, cy), 4 x 4 samples a pixel; `paint` gives each sample's colour and
/// opacity from its offset (dx, dy) from the centre, or an opacity of 0 for none.
template <class Paint>
void draw_disc(Canvas& canvas, double cx, double cy, double r, Paint paint) {
  for (int y = static_cast<int>(std::floor(cy - r)); y <= static_cast<int>(std::ceil(cy + r)); ++y)
    for (int x = static_cast<int>(std::floor(cx - r)); x <= static_cast<int>(std::ceil(cx + r)); ++x) {
      int sum[3] = {0, 0, 0}, cover = 0;
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) {
          const double dx = x + (sx + 0.5) / 4 - cx, dy = y + (sy + 0.5) / 4 - cy;
          if (dx * dx + dy * dy > r * r) continue;
          int alpha = 0;
          const Rgb c = paint(dx, dy, alpha);
          sum[0] += c.r * alpha, sum[1] += c.g * alpha, sum[2] += c.b * alpha, cover += alpha;
        }
      if (cover == 0) continue;
      const Rgb mean{static_cast<std::uint8_t>(sum[0] / cover), static_cast<std::uint8_t>(sum[1] / cover),
                     static_cast<std::uint8_t>(sum[2] / cover)};
      canvas.blend(x, y, mean, cover / 16);
    }
}

Rgb rgb(SrgbColor c) { return {c.r, c.g, c.b}; }

/// `text` cut short with an ellipsis, a whole character at a time, to at most `width` pixels.
std::string fitted(const Face& face, double size, std::string text, double width) {
  if (text_width(face, size, text) <= width) return text;
  const std::string ellipsis = "\xE2\x80\xA6";
  while (!text.empty() && text_width(face, size, text + ellipsis) > width) {
    std::size_t end = text.size() - 1;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;  // a UTF-8 lead byte
    text.erase(end);
    while (text.ends_with(" ")) text.pop_back();
  }
  return text + ellipsis;
}

/// One ball of the rack's row: in its colours with its number when it is on the table, else a faint ring.
void draw_ball(Canvas& canvas, const Fonts& f, double disc, double s, double cx, double cy, int number, bool up) {
  const double r = 0.5 * disc * s, ring = std::max(1.0, 1.5 * s);
  if (!up) {
    draw_disc(canvas, cx, cy, r, [&](double dx, double dy, int& alpha) {
      alpha = dx * dx + dy * dy >= (r - ring) * (r - ring) ? 110 : 0;
      return kDim;
    });
    return;
  }
  const Rgb color = rgb(ball_srgb(number)), ivory = rgb(kBallIvory);
  const bool stripe = ball_striped(number);
  draw_disc(canvas, cx, cy, r, [&](double dx, double dy, int& alpha) {
    alpha = 255;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= (r - ring) * (r - ring)) return Rgb{200, 206, 218};  // a light rim: the 8 on the dark panel
    if (d2 <= 0.25 * r * r) return ivory;                          // the number's disc
    return stripe && (dy < -0.64 * r || dy > 0.64 * r) ? ivory : color;
  });
  const std::string text = std::to_string(number);
  const double size = (number >= 10 ? 0.5 : 0.66) * r * 1.55;
  const double w = text_width(f.bold, size, text);
  draw_text(canvas, f.bold, size, cx - 0.5 * w, centred_baseline(f.bold, size, cy), text, kDark);
}

/// The panel's rows: the two players, the game and the shot, the rack's balls.
void draw_panel(Canvas& canvas, const Fonts& f, const Caption& c, double s, double x0, double x1, double top) {
  const double bottom = canvas.height() - kMarginBottom * s;
  canvas.fill(x0, top, x1, bottom, kPanel, kPanelAlpha);
  const double pad = kPad * s;
  const std::string corner[2] = {caption_game_name(c.rules), "SHOT " + std::to_string(c.shot + 1)};
  for (int p = 0; p < 2; ++p) {
    const double y = top + p * kNameRow * s, middle = y + 0.5 * kNameRow * s;
    const bool up = p == c.at_table;
    if (up) {
      canvas.fill(x0, y, x1, y + kNameRow * s, kRowLit, kRowAlpha);
      canvas.fill(x0, y, x0 + kAccentBar * s, y + kNameRow * s, kAccent, 255);
    }
    const Face& face = up ? f.bold : f.regular;
    const std::string name = p < static_cast<int>(c.players.size()) ? c.players[static_cast<std::size_t>(p)] : "";
    const double w = text_width(f.bold, kSmallSize * s, corner[p]);
    const double name_x = x0 + pad + kAccentBar * s;
    draw_text(canvas, face, kNameSize * s, name_x, centred_baseline(face, kNameSize * s, middle),
              fitted(face, kNameSize * s, name, x1 - pad - w - kTagPad * s - name_x), up ? kWhite : kDim);
    draw_text(canvas, f.bold, kSmallSize * s, x1 - pad - w, centred_baseline(f.bold, kSmallSize * s, middle), corner[p],
              kSmallText);
  }
  const double rule = top + 2 * kNameRow * s;
  canvas.fill(x0 + pad, rule, x1 - pad, rule + std::max(1.0, s), kSmallText, 80);
  const double cy = rule + 0.5 * kBallRow * s;
  const auto [disc, step] = disc_layout(c.rack.size());
  for (std::size_t i = 0; i < c.rack.size(); ++i) {
    const int number = c.rack[i];
    const bool up = std::find(c.on_table.begin(), c.on_table.end(), number) != c.on_table.end();
    draw_ball(canvas, f, disc, s, x0 + pad + (static_cast<double>(i) + 0.5) * step * s, cy, number, up);
  }
}

/// `text` in lines of at most `width` pixels, at most `most` (the last cut short with an
/// ellipsis when more is left). Lines break between the parts of a call (joined by " · ") where they
/// can, else between words.
std::vector<std::string> wrapped(const Face& face, double size, const std::string& text, double width, int most) {
  const std::string dot = " \xC2\xB7 ";
  std::vector<std::string> pieces;  // each part but the last keeps its dot, so a line can end in one
  for (std::size_t at = 0; at <= text.size();) {
    std::size_t end = text.find(dot, at);
    end = end == std::string::npos ? text.size() : end + dot.size();
    pieces.push_back(text.substr(at, end - at));
    at = end == text.size() ? text.size() + 1 : end;
  }
  std::vector<std::string> lines(1);
  const auto fits = [&](const std::string& line) { return text_width(face, size, line) <= width; };
  const auto trimmed = [](std::string line) { return line.ends_with(" ") ? line.substr(0, line.size() - 1) : line; };
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::string& piece = pieces[i];
    if (fits(trimmed(lines.back() + piece))) {
      lines.back() += piece;
      continue;
    }
    if (!lines.back().empty() && fits(trimmed(piece)) && static_cast<int>(lines.size()) < most) {
      lines.push_back(piece);  // a part that fits a line of its own starts one
      continue;
    }
    // Word by word: onto this line while they fit, then onto new ones.
    for (std::size_t at = 0; at < piece.size();) {
      std::size_t end = piece.find(' ', at);
      end = end == std::string::npos ? piece.size() : end + 1;
      const std::string word = piece.substr(at, end - at);
      if (!lines.back().empty() && !fits(trimmed(lines.back() + word))) {
        if (static_cast<int>(lines.size()) >= most) {
          lines.back() = trimmed(lines.back()) + "\xE2\x80\xA6";  // an ellipsis: more than the lines hold
          return lines;
        }
        lines.push_back("");
      }
      lines.back() += word;
      at = end;
    }
  }
  for (std::string& line : lines) {
    line = trimmed(line);
    if (line.ends_with(" \xC2\xB7")) line.erase(line.size() - 3);  // no dot at a line's end
  }
  return lines;
}

Rgb tag_color(CaptionCall::Kind kind) {
  switch (kind) {
    case CaptionCall::Kind::foul: return kFoulTag;
    case CaptionCall::Kind::push_out: return kInfoTag;
    case CaptionCall::Kind::winner: return kAccent;
    case CaptionCall::Kind::stopped: return kStoppedTag;
  }
  return kInfoTag;
}

/// A call's strip with its bottom at `bottom`: its coloured tag and its words. Returns its top.
double draw_call(Canvas& canvas, const Fonts& f, const CaptionCall& call, double s, double x0, double x1, double bottom,
                 double ceiling) {
  const double size = kCallSize * s, pad = kTagPad * s;
  const double tag = text_width(f.bold, size, call.title) + 2 * pad;
  if (bottom - kStrip * s < ceiling) return bottom;  // no room for even one line
  const int room = 1 + static_cast<int>(std::floor((bottom - kStrip * s - ceiling) / (kStripLine * s)));
  const std::vector<std::string> lines =
      wrapped(f.regular, size, call.text, x1 - x0 - tag - 2 * pad, std::min(kMostCallLines, room));
  const double top = bottom - (kStrip + (static_cast<double>(lines.size()) - 1) * kStripLine) * s;
  canvas.fill(x0, top, x1, bottom, kPanel, kPanelAlpha);
  const Rgb color = tag_color(call.kind);
  canvas.fill(x0, top, x0 + tag, bottom, color, 255);
  const double first = top + 0.5 * kStrip * s;
  draw_text(canvas, f.bold, size, x0 + pad, centred_baseline(f.bold, size, first), call.title,
            call.kind == CaptionCall::Kind::winner ? kDark : kWhite);
  for (std::size_t i = 0; i < lines.size(); ++i)
    draw_text(canvas, f.regular, size, x0 + tag + pad,
              centred_baseline(f.regular, size, first + static_cast<double>(i) * kStripLine * s), lines[i], kWhite);
  return top;
}

}  // namespace

CaptionBox lower_third_column(int rack_size, int width, int height, bool right) {
  const double s = layout_scale(height);
  const double step = disc_layout(static_cast<std::size_t>(std::max(rack_size, 0))).second;
  const double panel = s * std::max(kPanelMinWidth, 2 * kPad + rack_size * step);
  const double x0 = right ? width - s * kMarginX - panel : s * kMarginX;
  return {round_px(x0), height / 2, round_px(x0 + panel), height};
}

std::string lower_third_signature() { return kLowerThirdVersion + fonts().signature; }

bool lower_third_fonts(std::string& error) {
  if (fonts().regular.ok && fonts().bold.ok) return true;
  error =
      "the captions need the DejaVu fonts (DejaVuSans.ttf and DejaVuSans-Bold.ttf), which are not installed "
      "(Debian: fonts-dejavu-core); install them, or pass --captions off";
  return false;
}

}  // namespace bsim

namespace bsim {

bool draw_lower_third(std::vector<std::uint8_t>& srgb, int width, int height, const FrameCaption& frame,
                      std::string& error) {
  if (!lower_third_fonts(error)) return false;
  const Fonts& f = fonts();
  const Caption& c = frame.caption;
  Canvas canvas(srgb, width, height);
  const double s = layout_scale(height);
  const CaptionBox column = lower_third_column(static_cast<int>(c.rack.size()), width, height, frame.right);
  const double x0 = column.x0, x1 = column.x1;
  const double top = height - (kMarginBottom + 2 * kNameRow + kBallRow) * s;
  draw_panel(canvas, f, c, s, x0, x1, top);
  double bottom = top - kGap * s;
  // Never in the upper half, and a replay's tag always above the calls (they are cut short for it).
  const double ceiling = 0.5 * height + (c.replay ? (kStrip + kGap) * s : 0.0);
  for (auto call = c.calls.rbegin(); call != c.calls.rend(); ++call)
    bottom = draw_call(canvas, f, *call, s, x0, x1, bottom, ceiling) - kGap * s;
  if (c.replay) {
    const double size = kCallSize * s, w = text_width(f.bold, size, "REPLAY") + 2 * kTagPad * s;
    const double left = frame.right ? x1 - w : x0, up = bottom - kStrip * s;
    if (up >= 0.5 * height) {
      canvas.fill(left, up, left + w, bottom, kReplayTag, 255);
      draw_text(canvas, f.bold, size, left + kTagPad * s, centred_baseline(f.bold, size, up + 0.5 * kStrip * s),
                "REPLAY", kWhite);
    }
  }
  return true;
}

}  // namespace bsim
