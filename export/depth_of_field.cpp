#include "depth_of_field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bsim {

namespace {

/// Pixels a tap in front of the pixel must be more blurred than the pixel to lie over it as a
/// foreground of its own (less: the same surface, or a sharper thing in front).
constexpr float kLayer = 1.0f;

/// One tap of the spiral: its offset in pixels and its distance from the centre.
struct BlurTap {
  int dx = 0, dy = 0;
  float distance = 0;  ///< of the offset
  float nominal = 0;   ///< the spiral's radius at the tap, growing with its index
};

/// The golden-angle spiral (Vogel 1979) out to `radius`: tap k at sqrt(k kTapArea / pi), turned by
/// k golden angles, rounded to a pixel. The turns come from repeated multiplication by the golden
/// angle's cosine and sine, so no trigonometric function is called.
std::vector<BlurTap> spiral(double radius) {
  constexpr double kCos = -0.73736887807831963, kSin = 0.67549029426152374;  // of pi (3 - sqrt 5)
  std::vector<BlurTap> taps;
  double c = 1, s = 0;
  for (int k = 1;; ++k) {
    const double t = c * kCos - s * kSin;
    s = s * kCos + c * kSin;
    c = t;
    const double rho = std::sqrt(k * kTapArea / std::numbers::pi);
    if (rho > radius) break;
    const int dx = static_cast<int>(std::floor(rho * c + 0.5)), dy = static_cast<int>(std::floor(rho * s + 0.5));
    if (dx == 0 && dy == 0) continue;
    taps.push_back(
        {dx, dy, static_cast<float>(std::sqrt(static_cast<double>(dx * dx + dy * dy))), static_cast<float>(rho)});
  }
  return taps;
}

/// The radius below which a circle reaches no tap: the first tap's distance less half a pixel.
float sharp_radius() { return static_cast<float>(std::sqrt(kTapArea / std::numbers::pi)) - 0.5f; }

/// Whether a circle of radius r reaches a tap at `distance`: 0 to 1 over the pixel's width.
float reach(float distance, float r) {
  const float t = std::clamp(r - distance + 0.5f, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

/// The share of a circle's light a tap's pixel passes on: its area (kTapArea) over the circle's.
float spread(float r) {
  constexpr float kAreaOverPi = static_cast<float>(kTapArea / std::numbers::pi);
  return r * r > kAreaOverPi ? kAreaOverPi / (r * r) : 1.0f;
}

/// The picture being blurred: its light, depth, circles and each circle's spread (spread()), read from
/// the unblurred copy.
struct Source {
  int width = 0, height = 0;
  const float* rgb = nullptr;
  const float* depth = nullptr;
  const float* radius = nullptr;
  const float* spread = nullptr;
};

/// Running sums of light and weight.
struct Sum {
  float rgb[3] = {0, 0, 0};
  float weight = 0;
  void add(const float* c, float w) {
    for (int k = 0; k < 3; ++k) rgb[k] += w * c[k];
    weight += w;
  }
};

/// Pixel (x, y) gathered from the first `count` taps (their offsets in the picture's rows `offsets`,
/// good where no tap leaves the picture: `interior`), into `out`.
template <bool interior>
void gather_pixel(const Source& src, const std::vector<BlurTap>& taps, const std::vector<std::ptrdiff_t>& offsets,
                  std::size_t count, int x, int y, float* out) {
  const std::size_t centre = static_cast<std::size_t>(y) * src.width + x;
  const float* c = src.rgb + 3 * centre;
  const float zc = src.depth[centre], rc = src.radius[centre], behind_spread = spread(2.0f * rc);
  Sum near, far;
  far.add(c, src.spread[centre]);
  // What of the pixel's own layer the taps do not bring: the pixel itself where it is sharp, and where
  // its own circle (a blurred foreground) reaches over taps behind it, their light: c + shift / fill.
  float shift[3] = {0, 0, 0}, fill = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const BlurTap& tap = taps[k];
    const std::size_t q = interior ? static_cast<std::size_t>(static_cast<std::ptrdiff_t>(centre) + offsets[k])
                                   : static_cast<std::size_t>(std::clamp(y + tap.dy, 0, src.height - 1)) * src.width +
                                         static_cast<std::size_t>(std::clamp(x + tap.dx, 0, src.width - 1));
    const float* ci = src.rgb + 3 * q;
    const float zi = src.depth[q], ri = src.radius[q];
    if (zi < zc) {
      // In front: its own layer if it is more blurred than the pixel, else part of the pixel's.
      const float m = reach(tap.distance, ri);
      if (m > 0) (ri > rc + kLayer ? near : far).add(ci, m * src.spread[q]);
      continue;
    }
    // Behind (or level): a background spreads no further than twice the pixel's circle, no halo.
    const bool clamped = zi > zc && ri > 2.0f * rc;
    const float m = reach(tap.distance, clamped ? 2.0f * rc : ri);
    if (m > 0) far.add(ci, m * (clamped ? behind_spread : src.spread[q]));
    const float s = (1 - m) * reach(tap.distance, rc);
    if (s <= 0) continue;
    fill += s;
    for (int j = 0; j < 3; ++j) shift[j] += s * (ci[j] - c[j]);
  }
  float own[3];
  for (int j = 0; j < 3; ++j) {
    const float filler = fill > 0 ? c[j] + shift[j] / fill : c[j];
    own[j] = far.weight >= 1.0f ? far.rgb[j] / far.weight : far.rgb[j] + (1.0f - far.weight) * filler;
  }
  const float alpha = std::min(near.weight, 1.0f);
  for (int j = 0; j < 3; ++j) out[j] = near.weight > 0 ? own[j] + alpha * (near.rgb[j] / near.weight - own[j]) : own[j];
}

/// The largest circle in each tile and its eight neighbours: how far the spiral must go there.
std::vector<float> tile_reach(const std::vector<float>& radii, int width, int height, int tile, int tiles_x,
                              int tiles_y) {
  std::vector<float> largest(static_cast<std::size_t>(tiles_x) * tiles_y, 0.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float& t = largest[static_cast<std::size_t>(y / tile) * tiles_x + x / tile];
      t = std::max(t, radii[static_cast<std::size_t>(y) * width + x]);
    }
  std::vector<float> reach_radius(largest.size(), 0.0f);
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      float r = 0;
      for (int ny = std::max(0, ty - 1); ny <= std::min(tiles_y - 1, ty + 1); ++ny)
        for (int nx = std::max(0, tx - 1); nx <= std::min(tiles_x - 1, tx + 1); ++nx)
          r = std::max(r, largest[static_cast<std::size_t>(ny) * tiles_x + nx]);
      reach_radius[static_cast<std::size_t>(ty) * tiles_x + tx] = r;
    }
  return reach_radius;
}

}  // namespace

DepthPicture nearest_of_neighbours(const DepthPicture& depth) {
  DepthPicture out = depth;
  const int w = depth.width, h = depth.height;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float z = depth.depth[static_cast<std::size_t>(y) * w + x];
      for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx)
          z = std::min(z, depth.depth[static_cast<std::size_t>(ny) * w + nx]);
      out.depth[static_cast<std::size_t>(y) * w + x] = z;
    }
  return out;
}

std::vector<float> blur_radii(const DepthPicture& depth, const Lens& lens) {
  const double most = kMaxBlurRadius * depth.width / 1280.0;
  std::vector<float> radii(depth.depth.size());
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const double z = std::isfinite(depth.depth[i]) ? std::max<double>(depth.depth[i], 1e-3) : 1e6;
    radii[i] = static_cast<float>(std::min(most, 0.5 * std::abs(circle_of_confusion_px(lens, z, depth.width))));
  }
  return radii;
}

void gather_blur(HdrImage& image, const DepthPicture& depth, const std::vector<float>& radii) {
  const int width = image.width, height = image.height;
  if (width <= 0 || height <= 0) return;
  const float largest = *std::max_element(radii.begin(), radii.end());
  if (largest < sharp_radius()) return;
  const int tile = std::max(kBlurTile, static_cast<int>(std::ceil(largest)));
  const int tiles_x = (width + tile - 1) / tile, tiles_y = (height + tile - 1) / tile;
  const std::vector<float> reach_radius = tile_reach(radii, width, height, tile, tiles_x, tiles_y);
  const std::vector<BlurTap> taps = spiral(largest + 0.5);
  std::vector<std::ptrdiff_t> offsets;
  for (const BlurTap& t : taps) offsets.push_back(static_cast<std::ptrdiff_t>(t.dy) * width + t.dx);
  std::vector<float> spreads(radii.size());
  for (std::size_t i = 0; i < radii.size(); ++i) spreads[i] = spread(radii[i]);
  const std::vector<float> unblurred = image.rgb;
  const Source src{width, height, unblurred.data(), depth.depth.data(), radii.data(), spreads.data()};
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      const float r = reach_radius[static_cast<std::size_t>(ty) * tiles_x + tx];
      if (r < sharp_radius()) continue;  // nothing here reaches a tap: the pixels stay as they are
      // The taps out to the tile's reach; whether they all stay in the picture from every pixel of it.
      const auto end = std::find_if(taps.begin(), taps.end(), [&](const BlurTap& t) { return t.nominal > r + 0.5f; });
      const auto count = static_cast<std::size_t>(end - taps.begin());
      const int x0 = tx * tile, y0 = ty * tile, x1 = std::min(width, x0 + tile), y1 = std::min(height, y0 + tile);
      const int margin = static_cast<int>(std::ceil(r)) + 2;
      const bool interior = x0 >= margin && y0 >= margin && x1 + margin <= width && y1 + margin <= height;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          float* out = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x);
          if (interior)
            gather_pixel<true>(src, taps, offsets, count, x, y, out);
          else
            gather_pixel<false>(src, taps, offsets, count, x, y, out);
        }
    }
}

}  // namespace bsim
