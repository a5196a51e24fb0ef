#include "develop.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "depth_of_field.h"
#include "frame_lens.h"
#include "lower_third.h"
#include "png_file.h"

namespace bsim {

namespace {

/// Bumped whenever the pipeline's code changes what it makes from the same .hdr.
constexpr const char* kDevelopVersion = "develop 2";

/// The glare's point-spread function: a sum of Gaussians of growing radius, after the shape of a
/// lens's (and an eye's) glare PSF, a narrow core with a wide skirt falling off roughly as a power
/// of the angle (Spencer, Shirley, Zimmerman & Greenberg 1995, "Physically-based glare effects for
/// digital images", SIGGRAPH). Radii are in pixels of a 1280-pixel-wide picture and scale with the
/// width; each is blurred at a reduced resolution, 2, 4 and 8 times smaller, where it costs little.
struct GlareLobe {
  double sigma;  ///< pixels of a 1280-wide picture
  float weight;  ///< share of the scattered light; the shares add up to 1
};
constexpr std::array<GlareLobe, 3> kGlareLobes = {{{4.0, 0.55f}, {14.0, 0.3f}, {44.0, 0.15f}}};
constexpr double kGlareReferenceWidth = 1280.0;

/// Rec. 709 / sRGB luminance weights (ITU-R BT.709-6; IEC 61966-2-1 shares its primaries).
constexpr float kLumaR = 0.2126f, kLumaG = 0.7152f, kLumaB = 0.0722f;

/// SplitMix64's finaliser (Steele, Lea & Flood 2014): a 64-bit hash that spreads every input bit.
std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// e^-a for a >= 0 from basic arithmetic alone, the same bits on every CPU (glibc's exp picks an
/// FMA variant at run time, which may differ in the last bit).
double exp_neg(double a) {
  constexpr double kInvE = 0.36787944117144233;
  const int whole = static_cast<int>(a);
  const double f = a - whole;
  double term = 1.0, sum = 1.0;
  for (int k = 1; k <= 24; ++k) {
    term *= -f / k;
    sum += term;
  }
  for (int k = 0; k < whole; ++k) sum *= kInvE;
  return sum;
}

/// The sRGB decoding of an encoded value v in [0, 1] (IEC 61966-2-1): v / 12.92 at the foot, else
/// ((v + 0.055) / 1.055)^2.4, found by bisection on y^5 = t^12 so it uses no pow().
double srgb_decode(double v) {
  if (v <= 0.04045) return v / 12.92;
  const double t = (v + 0.055) / 1.055;
  const double t2 = t * t, t4 = t2 * t2, t12 = t4 * t4 * t4;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 64; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double m2 = mid * mid;
    (m2 * m2 * mid <= t12 ? lo : hi) = mid;
  }
  return lo;
}

/// Cells of the quick look-up into the sRGB steps: each narrower than the narrowest step between two
/// codes (1 / (255 x 12.92) at the foot), so a value is at most one step past its cell's first code.
constexpr int kSrgbCells = 8192;

/// The display-linear values at which the 8-bit sRGB code steps from k to k + 1 (the decoding of
/// (k + 0.5) / 255, so that a value takes its nearest code in the encoded scale), and the code at
/// the start of each cell.
struct SrgbTable {
  std::array<float, 255> steps{};
  std::array<std::uint8_t, kSrgbCells + 1> first{};
};

const SrgbTable& srgb_table() {
  static const SrgbTable table = [] {
    SrgbTable t;
    for (int k = 0; k < 255; ++k) t.steps[k] = static_cast<float>(srgb_decode((k + 0.5) / 255.0));
    for (int i = 0; i <= kSrgbCells; ++i) {
      const float start = static_cast<float>(i) / kSrgbCells;
      t.first[i] = static_cast<std::uint8_t>(std::upper_bound(t.steps.begin(), t.steps.end(), start) - t.steps.begin());
    }
    return t;
  }();
  return table;
}

/// One channel of a picture at some resolution, as a flat row-major array of three-float pixels.
struct Plane {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
  float* at(int x, int y) { return rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x); }
  const float* at(int x, int y) const { return rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x); }
};

Plane make_plane(int width, int height) {
  return {width, height, std::vector<float>(3 * static_cast<std::size_t>(width) * height, 0.0f)};
}

/// Half the size (rounded up), each pixel the mean of the 2x2 pixels it covers that exist: the mean
/// light, so the total light per area is kept.
Plane half_size(const Plane& in) {
  Plane out = make_plane((in.width + 1) / 2, (in.height + 1) / 2);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      float sum[3] = {0, 0, 0};
      int n = 0;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const int sx = 2 * x + dx, sy = 2 * y + dy;
          if (sx >= in.width || sy >= in.height) continue;
          const float* p = in.at(sx, sy);
          for (int c = 0; c < 3; ++c) sum[c] += p[c];
          ++n;
        }
      float* o = out.at(x, y);
      for (int c = 0; c < 3; ++c) o[c] = sum[c] / static_cast<float>(n);
    }
  return out;
}

/// The normalised taps of a Gaussian of `sigma` pixels, out to three sigma on each side.
std::vector<float> gaussian_taps(double sigma) {
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  std::vector<double> taps(2 * static_cast<std::size_t>(radius) + 1);
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) sum += taps[i + radius] = exp_neg(0.5 * i * i / (sigma * sigma));
  std::vector<float> out(taps.size());
  for (std::size_t i = 0; i < taps.size(); ++i) out[i] = static_cast<float>(taps[i] / sum);
  return out;
}

/// A separable Gaussian blur. Light that would land beyond the edges is lost, as light a lens
/// scatters off its sensor is.
void blur(Plane& plane, double sigma) {
  const std::vector<float> taps = gaussian_taps(sigma);
  const int radius = static_cast<int>(taps.size() / 2);
  Plane tmp = make_plane(plane.width, plane.height);
  for (int y = 0; y < plane.height; ++y)
    for (int x = 0; x < plane.width; ++x) {
      float sum[3] = {0, 0, 0};
      for (int i = std::max(-radius, -x); i <= std::min(radius, plane.width - 1 - x); ++i) {
        const float* p = plane.at(x + i, y);
        const float w = taps[i + radius];
        for (int c = 0; c < 3; ++c) sum[c] += w * p[c];
      }
      std::copy(sum, sum + 3, tmp.at(x, y));
    }
  for (int y = 0; y < plane.height; ++y)
    for (int x = 0; x < plane.width; ++x) {
      float sum[3] = {0, 0, 0};
      for (int i = std::max(-radius, -y); i <= std::min(radius, plane.height - 1 - y); ++i) {
        const float* p = tmp.at(x, y + i);
        const float w = taps[i + radius];
        for (int c = 0; c < 3; ++c) sum[c] += w * p[c];
      }
      std::copy(sum, sum + 3, plane.at(x, y));
    }
}

/// Where a pixel of a picture resized from `from` to `to` pixels samples the smaller one, bilinearly
/// with pixel centres aligned: between `lo` and `hi`, `t` of the way.
struct Tap {
  int lo = 0;
  int hi = 0;
  float t = 0.0f;
};

std::vector<Tap> resample_taps(int from, int to) {
  std::vector<Tap> taps(to);
  const double scale = static_cast<double>(from) / to;
  for (int i = 0; i < to; ++i) {
    const double f = std::clamp((i + 0.5) * scale - 0.5, 0.0, from - 1.0);
    taps[i].lo = static_cast<int>(f);
    taps[i].hi = std::min(taps[i].lo + 1, from - 1);
    taps[i].t = static_cast<float>(f - taps[i].lo);
  }
  return taps;
}

/// Adds `weight` times `low`, resampled bilinearly to `high`'s size.
void add_resampled(const Plane& low, float weight, Plane& high) {
  const std::vector<Tap> xs = resample_taps(low.width, high.width), ys = resample_taps(low.height, high.height);
  for (int y = 0; y < high.height; ++y) {
    const Tap ty = ys[y];
    for (int x = 0; x < high.width; ++x) {
      const Tap tx = xs[x];
      const float *a = low.at(tx.lo, ty.lo), *b = low.at(tx.hi, ty.lo), *c = low.at(tx.lo, ty.hi),
                  *d = low.at(tx.hi, ty.hi);
      float* o = high.at(x, y);
      for (int k = 0; k < 3; ++k) {
        const float top = a[k] + tx.t * (b[k] - a[k]), bottom = c[k] + tx.t * (d[k] - c[k]);
        o[k] += weight * (top + ty.t * (bottom - top));
      }
    }
  }
}

bool read_whole_file(const std::string& path, std::string& bytes) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) bytes.append(buffer, n);
  const bool ok = !std::ferror(file);
  std::fclose(file);
  if (!ok) errno = EIO;
  return ok;
}

/// Decodes a Radiance picture (Ward 1991, "Real Pixels", Graphics Gems II; the Radiance file format:
/// a text header, the resolution line "-Y H +X W", then scanlines of RGBE pixels, flat or in the
/// run-length form every writer uses for 8 to 32767 pixels a line). Strict about everything, since
/// stb_image's reader loops for ever on a truncated file. Returns what is wrong, or null.
const char* decode_radiance(const std::string& bytes, HdrImage& image) {
  std::size_t at = 0;
  auto line = [&](std::string& text) {
    const std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) return false;
    text = bytes.substr(at, end - at);
    at = end + 1;
    return true;
  };
  std::string text;
  if (!line(text) || (text != "#?RADIANCE" && text != "#?RGBE")) return "not a Radiance .hdr picture";
  for (;;) {
    if (!line(text)) return "the header has no end";
    if (text.empty()) break;
    if (text.rfind("FORMAT=", 0) == 0 && text != "FORMAT=32-bit_rle_rgbe") return "not in RGBE format";
  }
  int width = 0, height = 0;
  char tail = 0;
  if (!line(text) || std::sscanf(text.c_str(), "-Y %d +X %d%c", &height, &width, &tail) != 2 || width <= 0 ||
      height <= 0 || width > (1 << 16) || height > (1 << 16))
    return "no resolution line of the form -Y HEIGHT +X WIDTH";

  const auto w = static_cast<std::size_t>(width);
  std::vector<std::uint8_t> scan(4 * w);  // a scanline as RGBE quadruples
  auto byte = [&](std::uint8_t& b) {
    if (at >= bytes.size()) return false;
    b = static_cast<std::uint8_t>(bytes[at++]);
    return true;
  };
  image.width = width;
  image.height = height;
  image.rgb.assign(3 * w * height, 0.0f);
  for (int y = 0; y < height; ++y) {
    if (at + 4 > bytes.size()) return "truncated";
    const auto* head = reinterpret_cast<const std::uint8_t*>(bytes.data() + at);
    const bool run_length = width >= 8 && width < 32768 && head[0] == 2 && head[1] == 2 && !(head[2] & 0x80);
    if (run_length) {
      if ((static_cast<std::size_t>(head[2]) << 8 | head[3]) != w) return "a scanline of the wrong length";
      at += 4;
      for (int c = 0; c < 4; ++c) {  // each component's run-length encoded line in turn
        for (std::size_t x = 0; x < w;) {
          std::uint8_t count = 0, value = 0;
          if (!byte(count)) return "truncated";
          const bool run = count > 128;
          const std::size_t n = run ? count - 128u : count;
          if (n == 0 || x + n > w) return "bad run-length data";
          for (std::size_t i = 0; i < n; ++i, ++x) {
            if ((run && i == 0) || !run)
              if (!byte(value)) return "truncated";
            scan[4 * x + c] = value;
          }
        }
      }
    } else {
      if (head[0] == 1 && head[1] == 1 && head[2] == 1) return "old run-length data, not supported";
      if (at + 4 * w > bytes.size()) return "truncated";
      std::copy_n(bytes.data() + at, 4 * w, reinterpret_cast<char*>(scan.data()));
      at += 4 * w;
    }
    float* out = image.rgb.data() + 3 * w * y;
    for (std::size_t x = 0; x < w; ++x) {
      const std::uint8_t* p = scan.data() + 4 * x;
      if (p[3] == 0) continue;  // black
      // Ward's conversion: the mantissa's centre, (m + 0.5) / 256, times 2 to the exponent less 128.
      const float f = std::ldexp(1.0f, p[3] - (128 + 8));
      for (int c = 0; c < 3; ++c) out[3 * x + c] = (static_cast<float>(p[c]) + 0.5f) * f;
    }
  }
  return nullptr;
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

}  // namespace

std::string develop_signature() {
  std::string s = std::string(kDevelopVersion) + " exposure " + number(kExposure) + " white " + number(kToneWhite) +
                  " glare " + number(kGlareThreshold) + " " + number(kGlareShare);
  for (const GlareLobe& lobe : kGlareLobes) s += " " + number(lobe.sigma) + ":" + number(lobe.weight);
  s += " vignette " + number(kVignetteCornerTan) + " " + number(kOpenVignette) + " " + number(kClearVignetteAperture);
  s += " blur " + number(kMaxBlurRadius) + " " + number(kTapArea) + " " + std::to_string(kBlurTile);
  s += " aberration " + number(kRedScale) + " " + number(kBlueScale);
  s += " grain " + number(kGrainShot) + " " + number(kGrainFloor) + " " + number(kGrainChroma);
  return s + " saturation " + number(kSaturation);
}

bool read_hdr(const std::string& path, HdrImage& image, std::string& error) {
  std::string bytes;
  if (!read_whole_file(path, bytes)) {
    error = "cannot read " + path + ": " + std::strerror(errno);
    return false;
  }
  const char* problem = decode_radiance(bytes, image);
  if (problem) {
    error = "cannot read " + path + ": " + problem;
    return false;
  }
  return true;
}

float tone_curve(float x) {
  // Hable 2010, "Uncharted 2: HDR Lighting" (GDC) and "Filmic Tonemapping Operators": a rational fit
  // of a film's response, a toe, a straight middle and a long shoulder that rolls highlights off
  // towards white. The talk's shoulder, middle and toe shape (A to D, F) with half its toe strength
  // (E 0.005 for 0.01), so the dim room keeps its detail, and white at 6 for 11.2, so the lamp's
  // reflections reach white. With kExposure 1.6, POV-Ray's mid grey (0.18) stays at 0.188, its 0.5
  // becomes 0.44, its 1 (where it used to clip) 0.66 and its 2 0.86.
  constexpr float a = 0.22f, b = 0.30f, c = 0.10f, d = 0.20f, e = 0.005f, f = 0.30f;
  auto curve = [](float v) { return (v * (a * v + c * b) + d * e) / (v * (a * v + b) + d * f) - e / f; };
  static const float white = curve(kToneWhite);
  if (!(x > 0.0f)) return 0.0f;  // also NaN
  if (x >= kToneWhite) return 1.0f;
  return std::min(curve(x) / white, 1.0f);
}

std::uint8_t encode_srgb8(float linear) {
  const SrgbTable& table = srgb_table();
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  int code = table.first[static_cast<int>(linear * kSrgbCells)];
  while (code < 255 && linear >= table.steps[code]) ++code;
  while (code > 0 && linear < table.steps[code - 1]) --code;  // a product rounded up into the next cell
  return static_cast<std::uint8_t>(code);
}

float vignette(int x, int y, int width, int height) {
  // Natural vignetting: the irradiance a lens forms falls as cos^4 of the field angle (the cosine
  // fourth law; e.g. Ray, "Applied Photographic Optics", 3rd ed., ch. 30), here with
  // cos^4 = 1 / (1 + tan^2)^2 and the corner at kVignetteCornerTan.
  const double cx = 0.5 * width, cy = 0.5 * height;
  const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
  const double tan2 = (dx * dx + dy * dy) / (cx * cx + cy * cy) * (kVignetteCornerTan * kVignetteCornerTan);
  const double c2 = 1.0 / (1.0 + tan2);
  return static_cast<float>(c2 * c2);
}

float vignette(int x, int y, int width, int height, double aperture) {
  // The cos^4 law and, wide open, the lens's own fall-off (its barrel's rims cut the oblique pencils):
  // 1 - k r^2, k falling linearly with the f-number to nothing at kClearVignetteAperture.
  const double k = kOpenVignette *
                   std::clamp((kClearVignetteAperture - aperture) / (kClearVignetteAperture - kOpenAperture), 0.0, 1.0);
  const double cx = 0.5 * width, cy = 0.5 * height;
  const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
  return static_cast<float>(vignette(x, y, width, height) * (1.0 - k * (dx * dx + dy * dy) / (cx * cx + cy * cy)));
}

void expose(HdrImage& image) { expose(image, kClearVignetteAperture); }

void expose(HdrImage& image, double aperture) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float f = kExposure * vignette(x, y, image.width, image.height, aperture);
      float* p = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * image.width + x);
      for (int c = 0; c < 3; ++c) p[c] *= f;
    }
}

double chromatic_shift(double x, double y, int width, int height, bool red) {
  const double dx = x - 0.5 * width, dy = y - 0.5 * height;
  return std::sqrt(dx * dx + dy * dy) * (1.0 - 1.0 / (red ? kRedScale : kBlueScale));
}

void chromatic_aberration(HdrImage& image) {
  const int w = image.width, h = image.height;
  if (w <= 0 || h <= 0) return;
  const std::vector<float> source = image.rgb;
  const double cx = 0.5 * w, cy = 0.5 * h;
  for (const auto& [channel_index, channel_scale] : {std::pair{0, kRedScale}, std::pair{2, kBlueScale}}) {
    const int channel = channel_index;  // lambdas capture a variable, not a structured binding
    const double scale = channel_scale;
    // Pixel (x, y) of a picture `scale` times larger shows what lies at the centre + offset / scale.
    const std::vector<Tap> xs = [&] {
      std::vector<Tap> taps(static_cast<std::size_t>(w));
      for (int x = 0; x < w; ++x) {
        const double f = std::clamp(cx + (x + 0.5 - cx) / scale - 0.5, 0.0, w - 1.0);
        taps[static_cast<std::size_t>(x)] = {static_cast<int>(f), std::min(static_cast<int>(f) + 1, w - 1),
                                             static_cast<float>(f - static_cast<int>(f))};
      }
      return taps;
    }();
    for (int y = 0; y < h; ++y) {
      const double fy = std::clamp(cy + (y + 0.5 - cy) / scale - 0.5, 0.0, h - 1.0);
      const int y0 = static_cast<int>(fy), y1 = std::min(y0 + 1, h - 1);
      const float ty = static_cast<float>(fy - y0);
      for (int x = 0; x < w; ++x) {
        const Tap& tx = xs[static_cast<std::size_t>(x)];
        auto at = [&](int px, int py) { return source[3 * (static_cast<std::size_t>(py) * w + px) + channel]; };
        const float top = at(tx.lo, y0) + tx.t * (at(tx.hi, y0) - at(tx.lo, y0));
        const float bottom = at(tx.lo, y1) + tx.t * (at(tx.hi, y1) - at(tx.lo, y1));
        image.rgb[3 * (static_cast<std::size_t>(y) * w + x) + channel] = top + ty * (bottom - top);
      }
    }
  }
}

void add_grain(HdrImage& image, int frame) {
  // A normal deviate from four 16-bit uniforms of a 64-bit hash (their sum, centred and scaled to unit
  // variance: the Irwin-Hall distribution, close to normal), so no log or cosine is called.
  constexpr double kSqrt3 = 1.7320508075688772;
  auto normal = [](std::uint64_t h) {
    double sum = 0;
    for (int k = 0; k < 4; ++k) sum += (static_cast<double>((h >> (16 * k)) & 0xffff) + 0.5) / 65536.0;
    return static_cast<float>((sum - 2.0) * kSqrt3);
  };
  // The frame's seed: a hash of its number (salted, so frame 0 is no special pattern).
  const std::uint64_t number = static_cast<std::uint32_t>(frame);
  const std::uint64_t seed = mix64(0x6772061696e5f31ULL ^ number);
  const float luma = static_cast<float>(1.0 / std::sqrt(1.0 + kGrainChroma * kGrainChroma));
  const float chroma = static_cast<float>(kGrainChroma) * luma;
  const std::size_t pixels = image.rgb.size() / 3;
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint64_t base = seed + 4 * static_cast<std::uint64_t>(i);
    const float shared = luma * normal(mix64(base));
    for (int c = 0; c < 3; ++c) {
      float& v = image.rgb[3 * i + c];
      const double sigma = std::sqrt(kGrainShot * std::max(0.0f, v) + kGrainFloor);
      v += static_cast<float>(sigma) * (shared + chroma * normal(mix64(base + 1 + c)));
    }
  }
}

void add_glare(HdrImage& image) {
  if (image.width <= 0 || image.height <= 0) return;
  // The scattered light: kGlareShare of each pixel's light above the threshold, taken by luminance
  // so it keeps the pixel's hue.
  Plane scattered = make_plane(image.width, image.height);
  bool any = false;
  for (std::size_t i = 0; i < scattered.rgb.size(); i += 3) {
    const float* p = image.rgb.data() + i;
    const float luma = kLumaR * p[0] + kLumaG * p[1] + kLumaB * p[2];
    if (!(luma > kGlareThreshold)) continue;
    const float share = kGlareShare * (luma - kGlareThreshold) / luma;
    for (int c = 0; c < 3; ++c) scattered.rgb[i + c] = share * p[c];
    any = true;
  }
  if (!any) return;

  // Each lobe blurred at the resolution that suits its radius, then summed from the coarsest up.
  const double scale = image.width / kGlareReferenceWidth;
  std::array<Plane, kGlareLobes.size()> levels;
  Plane source = half_size(scattered);
  for (std::size_t k = 0; k < kGlareLobes.size(); ++k) {
    if (k > 0) source = half_size(source);
    levels[k] = source;
    blur(levels[k], kGlareLobes[k].sigma * scale * levels[k].width / image.width);
  }
  Plane sum = make_plane(levels.back().width, levels.back().height);
  for (std::size_t k = kGlareLobes.size(); k-- > 0;) {
    Plane finer = make_plane(levels[k].width, levels[k].height);
    add_resampled(levels[k], kGlareLobes[k].weight, finer);
    add_resampled(sum, 1.0f, finer);
    sum = std::move(finer);
  }
  // The scattered light leaves its pixel and lands spread round it.
  for (std::size_t i = 0; i < scattered.rgb.size(); ++i) image.rgb[i] -= scattered.rgb[i];
  Plane whole{image.width, image.height, std::move(image.rgb)};
  add_resampled(sum, 1.0f, whole);
  image.rgb = std::move(whole.rgb);
}

void saturate(float& r, float& g, float& b) {
  const float luma = kLumaR * r + kLumaG * g + kLumaB * b;
  r = std::max(0.0f, luma + kSaturation * (r - luma));
  g = std::max(0.0f, luma + kSaturation * (g - luma));
  b = std::max(0.0f, luma + kSaturation * (b - luma));
}

std::vector<std::uint8_t> tone_map(const HdrImage& image) {
  std::vector<std::uint8_t> out(image.rgb.size());
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    float r = tone_curve(image.rgb[i]), g = tone_curve(image.rgb[i + 1]), b = tone_curve(image.rgb[i + 2]);
    saturate(r, g, b);
    out[i] = encode_srgb8(r);
    out[i + 1] = encode_srgb8(g);
    out[i + 2] = encode_srgb8(b);
  }
  return out;
}

std::vector<std::uint8_t> develop(HdrImage image, const DevelopLens& lens) {
  if (!lens.frame || !lens.scene) {
    expose(image);
    add_glare(image);
    return tone_map(image);
  }
  const FrameLens& frame = *lens.frame;
  expose(image, frame.lens.aperture);
  // The camera POV-Ray renders from, its field of view from the lens (the sensor's half width over
  // the focal length), so no tangent is taken here.
  const CameraView view(frame.pose, CameraView::HalfWidth{0.5 * kSensorWidthMm / frame.lens.focal_mm},
                        static_cast<double>(image.width) / image.height);
  const DepthPicture depth =
      nearest_of_neighbours(cast_depth(*lens.scene, frame.moving, view, image.width, image.height));
  gather_blur(image, depth, blur_radii(depth, frame.lens));
  chromatic_aberration(image);
  add_glare(image);
  add_grain(image, frame.frame);
  return tone_map(image);
}

bool develop_to_png(HdrImage image, const std::string& png_path, std::string& error, const FrameCaption* caption,
                    const DevelopLens& lens) {
  const int width = image.width, height = image.height;
  std::vector<std::uint8_t> picture = develop(std::move(image), lens);
  if (caption && !draw_lower_third(picture, width, height, *caption, error)) return false;
  return write_png(png_path, picture, width, height, error);
}

bool develop_file(const std::string& hdr_path, const std::string& png_path, std::string& error) {
  HdrImage image;
  return read_hdr(hdr_path, image, error) && develop_to_png(std::move(image), png_path, error);
}

}  // namespace bsim
