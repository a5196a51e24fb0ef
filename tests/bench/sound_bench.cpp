// sound_bench: the sound track's figures. The parts of the built-in break's track (loudness of the
// impacts, the rolling, the reverberation and the room tone; the finished track's loudness, true
// peak and quietest 100 ms; the time it takes), then our ball-ball click beside a recorded one
// (Debian's foobillardplus-data, ball_ball.raw: 16-bit stereo at 22.05 kHz, read here and never
// shipped or mixed): spectral centroid, attack and decay time, side by side. With --picture FILE it
// draws both clicks' spectrograms side by side into a PNG.
//   sound_bench [--recording FILE] [--picture FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_easy_font.h>
#include <stb_image_write.h>

#include "builtin_scene.h"
#include "loudness.h"
#include "rolling.h"
#include "room.h"
#include "shot.h"
#include "sound_meter.h"
#include "sound_mix.h"
#include "sound_synth.h"
#include "soundtrack.h"

namespace {

using namespace bsim;
constexpr double kPi = std::numbers::pi;
constexpr const char* kDefaultRecording = "/usr/share/games/foobillardplus/data/ball_ball.raw";

struct Mono {
  std::vector<double> x;
  int rate = kSampleRate;
};

/// The raw recording, both channels averaged; empty if it cannot be read.
Mono read_raw(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Mono m;
  m.rate = 22050;
  for (std::size_t i = 0; i + 3 < bytes.size(); i += 4) {
    std::int16_t l, r;
    std::memcpy(&l, &bytes[i], 2);
    std::memcpy(&r, &bytes[i + 2], 2);
    m.x.push_back((l + r) / 65536.0);
  }
  return m;
}

/// From the first sample above 5% of the peak, `seconds` long (zero-padded).
Mono from_onset(const Mono& m, double seconds) {
  double peak = 0;
  for (double v : m.x) peak = std::max(peak, std::abs(v));
  std::size_t start = 0;
  while (start < m.x.size() && std::abs(m.x[start]) < 0.05 * peak) ++start;
  start = start > 8 ? start - 8 : 0;
  Mono out;
  out.rate = m.rate;
  out.x.assign(static_cast<std::size_t>(seconds * m.rate), 0.0);
  for (std::size_t i = 0; i < out.x.size() && start + i < m.x.size(); ++i) out.x[i] = m.x[start + i];
  return out;
}

/// Hz: the magnitude-weighted mean frequency of the first `seconds` below `top` Hz (Hann window).
double spectral_centroid(const Mono& m, double top, double seconds = 0.05) {
  const auto n = std::min(m.x.size(), static_cast<std::size_t>(seconds * m.rate));
  double weighted = 0, total = 0;
  for (std::size_t k = 1; k < n / 2; ++k) {
    const double f = static_cast<double>(k) * m.rate / static_cast<double>(n);
    if (f > top) break;
    double re = 0, im = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 - 0.5 * std::cos(2 * kPi * static_cast<double>(i) / static_cast<double>(n));
      const double phase = 2 * kPi * static_cast<double>(k * i) / static_cast<double>(n);
      re += w * m.x[i] * std::cos(phase);
      im -= w * m.x[i] * std::sin(phase);
    }
    const double magnitude = std::hypot(re, im);
    weighted += f * magnitude;
    total += magnitude;
  }
  return total > 0 ? weighted / total : 0;
}

/// The RMS envelope over 0.5 ms windows, one value per sample.
std::vector<double> envelope(const Mono& m) {
  const auto half = static_cast<std::size_t>(0.00025 * m.rate) + 1;
  std::vector<double> env(m.x.size());
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t j = i >= half ? i - half : 0; j < std::min(m.x.size(), i + half + 1); ++j, ++count)
      sum += m.x[j] * m.x[j];
    env[i] = std::sqrt(sum / static_cast<double>(count));
  }
  return env;
}

struct Shape {
  double attack_ms;   ///< from 10% to 90% of the envelope's peak
  double decay_ms;    ///< from the peak until the envelope stays under -20 dB of it
  double decay40_ms;  ///< ... under -40 dB
};

Shape shape(const Mono& m) {
  const std::vector<double> env = envelope(m);
  const auto top = static_cast<std::size_t>(std::max_element(env.begin(), env.end()) - env.begin());
  const double peak = env[top];
  std::size_t a10 = 0, a90 = 0;
  while (a10 < top && env[a10] < 0.1 * peak) ++a10;
  while (a90 < top && env[a90] < 0.9 * peak) ++a90;
  auto stays_under = [&](double level) {
    std::size_t last = top;
    for (std::size_t i = top; i < env.size(); ++i)
      if (env[i] >= level * peak) last = i;
    return 1000.0 * static_cast<double>(last - top) / m.rate;
  };
  return {1000.0 * static_cast<double>(a90 - a10) / m.rate, stays_under(0.1), stays_under(0.01)};
}

/// dB: the peak over the RMS of the first `seconds` (the balance of the click and its ring).
double crest_db(const Mono& m, double seconds) {
  const std::size_t n = std::min(m.x.size(), static_cast<std::size_t>(seconds * m.rate));
  double top = 0, sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    top = std::max(top, std::abs(m.x[i]));
    sum += m.x[i] * m.x[i];
  }
  return n > 0 && sum > 0 ? 20 * std::log10(top / std::sqrt(sum / static_cast<double>(n))) : 0.0;
}

Mono our_click(double speed) {
  const PhysicsParams physics;
  const std::vector<float> s = synth_impact(SoundKind::ball_ball, speed, 7, physics, kSampleRate);
  Mono m;
  m.x.assign(s.begin(), s.end());
  m.x.resize(static_cast<std::size_t>(0.2 * kSampleRate), 0.0);
  return m;
}

// --- The picture --------------------------------------------------------------------------------

constexpr int kPanelWidth = 480, kPanelHeight = 360, kMargin = 56, kTop = 40;
constexpr double kPictureSeconds = 0.12, kPictureHz = 24000, kRangeDb = 90;

struct Canvas {
  int width, height;
  std::vector<std::uint8_t> rgb;
  void set(int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const auto at = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
    rgb[at] = r;
    rgb[at + 1] = g;
    rgb[at + 2] = b;
  }
  /// Text with stb_easy_font's quads, drawn at twice their size.
  void text(int x, int y, const std::string& s) {
    static char buffer[60000];
    const int quads = stb_easy_font_print(0, 0, const_cast<char*>(s.c_str()), nullptr, buffer, sizeof buffer);
    const auto* v = reinterpret_cast<const float*>(buffer);
    for (int q = 0; q < quads; ++q) {
      const float* quad = v + q * 16;  // four vertices of x, y, z, colour
      const int x0 = static_cast<int>(quad[0]), y0 = static_cast<int>(quad[1]);
      const int x1 = static_cast<int>(quad[8]), y1 = static_cast<int>(quad[9]);
      for (int yy = 2 * y0; yy < 2 * y1; ++yy)
        for (int xx = 2 * x0; xx < 2 * x1; ++xx) set(x + xx, y + yy, 230, 230, 230);
    }
  }
};

/// A dark-to-bright colour map (black, purple, red, orange, yellow, white) of t in [0, 1].
void colour(double t, std::uint8_t& r, std::uint8_t& g, std::uint8_t& b) {
  static const double stops[][3] = {{0, 0, 4},      {80, 18, 123},  {190, 55, 82},
                                    {245, 125, 21}, {250, 215, 80}, {252, 255, 230}};
  t = std::clamp(t, 0.0, 1.0) * 5;
  const int k = std::min(4, static_cast<int>(t));
  const double f = t - k;
  r = static_cast<std::uint8_t>(stops[k][0] + f * (stops[k + 1][0] - stops[k][0]));
  g = static_cast<std::uint8_t>(stops[k][1] + f * (stops[k + 1][1] - stops[k][1]));
  b = static_cast<std::uint8_t>(stops[k][2] + f * (stops[k + 1][2] - stops[k][2]));
}

/// One spectrogram (5.3 ms Hann windows, each column its own) into the panel at (x0, y0), levels in
/// dB under the panel's loudest cell.
void draw_panel(Canvas& c, int x0, int y0, const Mono& m, const std::string& title) {
  const auto window = static_cast<std::size_t>(std::lround(0.00533 * m.rate));
  const auto bins = window / 2;
  std::vector<std::vector<double>> cells(kPanelWidth, std::vector<double>(bins, 0.0));
  double loudest = 1e-30;
  for (int col = 0; col < kPanelWidth; ++col) {
    const double t = kPictureSeconds * col / kPanelWidth;
    const auto centre = static_cast<long long>(t * m.rate);
    for (std::size_t k = 0; k < bins; ++k) {
      double re = 0, im = 0;
      for (std::size_t i = 0; i < window; ++i) {
        const long long at = centre - static_cast<long long>(window / 2) + static_cast<long long>(i);
        if (at < 0 || at >= static_cast<long long>(m.x.size())) continue;
        const double w = 0.5 - 0.5 * std::cos(2 * kPi * static_cast<double>(i) / static_cast<double>(window));
        const double phase = 2 * kPi * static_cast<double>(k * i) / static_cast<double>(window);
        re += w * m.x[static_cast<std::size_t>(at)] * std::cos(phase);
        im -= w * m.x[static_cast<std::size_t>(at)] * std::sin(phase);
      }
      cells[static_cast<std::size_t>(col)][k] = re * re + im * im;
      loudest = std::max(loudest, re * re + im * im);
    }
  }
  for (int col = 0; col < kPanelWidth; ++col)
    for (int row = 0; row < kPanelHeight; ++row) {
      const double f = kPictureHz * (kPanelHeight - 1 - row) / kPanelHeight;
      const double bin = f / m.rate * static_cast<double>(window);
      double db = -kRangeDb;
      if (bin < static_cast<double>(bins)) {
        const double p = cells[static_cast<std::size_t>(col)][static_cast<std::size_t>(bin)];
        db = p > 0 ? 10 * std::log10(p / loudest) : -kRangeDb;
      }
      std::uint8_t r, g, b;
      colour(1 + db / kRangeDb, r, g, b);
      c.set(x0 + col, y0 + row, r, g, b);
    }
  // Axes: a tick every 20 ms and every 4 kHz, labelled.
  for (int ms = 0; ms <= 120; ms += 20) {
    const int x = x0 + static_cast<int>(ms / 1000.0 / kPictureSeconds * kPanelWidth);
    for (int d = 0; d < 6; ++d) c.set(x, y0 + kPanelHeight + d, 230, 230, 230);
    c.text(x - 8, y0 + kPanelHeight + 8, std::to_string(ms));
  }
  for (int khz = 0; khz <= 24; khz += 4) {
    const int y = y0 + kPanelHeight - 1 - static_cast<int>(khz * 1000.0 / kPictureHz * kPanelHeight);
    for (int d = 1; d < 7; ++d) c.set(x0 - d, y, 230, 230, 230);
    c.text(x0 - 34, y - 6, std::to_string(khz));
  }
  c.text(x0, y0 - 28, title);
}

bool write_picture(const std::string& path, const Mono& recorded, const Mono& ours) {
  Canvas c{2 * (kPanelWidth + kMargin) + 40, kTop + kPanelHeight + 70, {}};
  c.rgb.assign(static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height) * 3, 16);
  draw_panel(c, kMargin, kTop, recorded, "recorded click (foobillardplus, 22.05 kHz)");
  draw_panel(c, 2 * kMargin + kPanelWidth + 10, kTop, ours, "our click at 2 m/s (48 kHz)");
  c.text(kMargin, kTop + kPanelHeight + 40,
         "kHz up, ms across; 0 to -90 dB under each picture's loudest cell; 5.3 ms windows");
  return stbi_write_png(path.c_str(), c.width, c.height, 3, c.rgb.data(), c.width * 3) != 0;
}

double loudness_of(const AudioBuffer& a) {
  const auto l = integrated_loudness(a);
  return l ? *l : -200;
}

void break_figures() {
  using Clock = std::chrono::steady_clock;
  auto result = load_shot(builtin_scene_text(), kBuiltinSceneName);
  if (!result.scripted()) {
    std::printf("the built-in break does not load\n");
    return;
  }
  const Shot& shot = *result.shot;
  const SoundSource source{shot.scene, shot.timeline, *shot.camera};
  const auto n = static_cast<std::size_t>(std::llround(shot.timeline.duration() * kSampleRate));
  auto silence = [&] {
    AudioBuffer a;
    a.left.assign(n, 0.0f);
    a.right.assign(n, 0.0f);
    return a;
  };
  AudioBuffer impacts = silence(), rolling = silence(), reverb = silence();
  std::vector<float> send(n, 0.0f);
  mix_cues(sound_cues(source), shot.timeline.physics(), 0.005, impacts, &send);
  mix_rolling(source, rolling, &send);
  add_reverb(send, reverb);
  const AudioBuffer tone = room_tone(n, 1);
  std::printf("the built-in break's sound track (%.1f s), before the level stage:\n", shot.timeline.duration());
  std::printf("  impacts   %6.1f LUFS  true peak %6.1f dBTP\n", loudness_of(impacts), to_db(true_peak(impacts)));
  std::printf("  rolling   %6.1f LUFS  true peak %6.1f dBTP\n", loudness_of(rolling), to_db(true_peak(rolling)));
  std::printf("  reverb    %6.1f LUFS\n", loudness_of(reverb));
  std::printf("  room tone %6.1f LUFS  (fixed, after the level stage)\n", loudness_of(tone));
  AudioBuffer track;
  std::string error;
  const auto t0 = Clock::now();
  mix_soundtrack(source, {.lead = 0.005, .music_path = {}, .level = {}}, n, track, error);
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  std::printf(
      "finished: %.2f LUFS (calibrated: the break at %.0f), true peak %.2f dBTP, quietest 100 ms %.1f dBFS, made in "
      "%.0f ms\n\n",
      loudness_of(track), kDefaultLoudness, to_db(true_peak(track)), test::quietest_window_db(track, 0.1), ms);
}

}  // namespace

int main(int argc, char** argv) {
  std::string recording = kDefaultRecording, picture;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--recording" && i + 1 < argc) {
      recording = argv[++i];
    } else if (a == "--picture" && i + 1 < argc) {
      picture = argv[++i];
    } else {
      std::fprintf(stderr, "usage: sound_bench [--recording FILE] [--picture FILE]\n");
      return 2;
    }
  }
  break_figures();
  const Mono raw = read_raw(recording);
  if (raw.x.empty()) {
    std::fprintf(stderr, "%s: cannot read the recording (apt-get install foobillardplus-data)\n", recording.c_str());
    return 1;
  }
  const Mono recorded = from_onset(raw, 0.15);
  std::printf("ball-ball click: recorded (%s) vs ours\n", recording.c_str());
  std::printf(
      "centroid: over the first 50 ms below 11 kHz (the recording's band), over all, and over the first 3 ms\n");
  std::printf("%-22s %14s %14s %14s %14s %14s %12s\n", "", "centroid <11k", "centroid all", "first 3 ms",
              "attack 10-90", "decay -20/-40", "peak/100 ms");
  auto row = [](const std::string& name, const Mono& m) {
    const Shape s = shape(m);
    std::printf("%-22s %11.0f Hz %11.0f Hz %11.0f Hz %11.2f ms %6.1f/%.1f ms %9.1f dB\n", name.c_str(),
                spectral_centroid(m, 11025), spectral_centroid(m, m.rate / 2.0),
                spectral_centroid(m, m.rate / 2.0, 0.003), s.attack_ms, s.decay_ms, s.decay40_ms, crest_db(m, 0.1));
  };
  row("recorded", recorded);
  for (double speed : {0.5, 2.0, 5.0}) {
    char name[40];
    std::snprintf(name, sizeof name, "ours at %.1f m/s", speed);
    row(name, from_onset(our_click(speed), 0.15));
  }
  if (!picture.empty()) {
    if (!write_picture(picture, recorded, from_onset(our_click(2.0), 0.15))) {
      std::fprintf(stderr, "cannot write %s\n", picture.c_str());
      return 1;
    }
    std::printf("\nwrote %s\n", picture.c_str());
  }
  return 0;
}
