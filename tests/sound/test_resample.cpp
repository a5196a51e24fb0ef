// A recording played slower: half speed is an octave lower and twice as long, with nothing above the
// new band (the replay's sound, resample.h).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "audio_buffer.h"
#include "resample.h"

using namespace bsim;

namespace {

std::vector<float> sine(double hz, std::size_t count) {
  std::vector<float> wave(count);
  for (std::size_t i = 0; i < count; ++i)
    wave[i] = static_cast<float>(0.5 * std::sin(2 * std::numbers::pi * hz * static_cast<double>(i) / kSampleRate));
  return wave;
}

/// The amplitude of `wave`'s component at `hz` (a single-bin DFT over its middle half).
double amplitude_at(const std::vector<float>& wave, double hz) {
  const std::size_t from = wave.size() / 4, to = 3 * wave.size() / 4;
  double re = 0, im = 0;
  for (std::size_t i = from; i < to; ++i) {
    const double a = 2 * std::numbers::pi * hz * static_cast<double>(i) / kSampleRate;
    re += wave[i] * std::cos(a);
    im += wave[i] * std::sin(a);
  }
  return 2 * std::hypot(re, im) / static_cast<double>(to - from);
}

/// Rising zero crossings per second over the middle half.
double crossings_per_second(const std::vector<float>& wave) {
  const std::size_t from = wave.size() / 4, to = 3 * wave.size() / 4;
  int rising = 0;
  for (std::size_t i = from + 1; i < to; ++i) rising += wave[i - 1] < 0 && wave[i] >= 0;
  return rising * static_cast<double>(kSampleRate) / static_cast<double>(to - from);
}

}  // namespace

TEST_SUITE("resample") {
  TEST_CASE("half speed: a 1 kHz tone becomes 500 Hz, twice as long, as loud") {
    const std::vector<float> tone = sine(1000, kSampleRate / 2);
    const std::vector<float> slow = resample(tone, 0, 0.5, 2 * tone.size());
    REQUIRE(slow.size() == 2 * tone.size());
    CHECK(crossings_per_second(tone) == doctest::Approx(1000).epsilon(0.01));
    CHECK(crossings_per_second(slow) == doctest::Approx(500).epsilon(0.01));
    CHECK(amplitude_at(slow, 500) == doctest::Approx(0.5).epsilon(0.01));
    CHECK(amplitude_at(slow, 1000) < 1e-3);
    // Every other sample is an original one, read back as it was.
    for (std::size_t i = 200; i < 400; i += 2) CHECK(slow[i] == doctest::Approx(tone[i / 2]).epsilon(0.005));
  }

  TEST_CASE("a tone high in the original band leaves no image above the slowed band") {
    // 20 kHz slowed to 10 kHz; a plain linear interpolation would leave its image at 24 - 10 = 14 kHz.
    const std::vector<float> tone = sine(20000, kSampleRate / 4);
    const std::vector<float> slow = resample(tone, 0, 0.5, 2 * tone.size());
    CHECK(amplitude_at(slow, 14000) < 0.005);
    CHECK(amplitude_at(slow, 10000) > 0.2);
  }

  TEST_CASE("outside the recording there is silence; the same input gives the same samples") {
    const std::vector<float> tone = sine(440, 4800);
    const std::vector<float> before = resample(tone, -10000, 0.5, 100);
    for (float v : before) CHECK(v == 0.0f);
    CHECK(resample(tone, 123.25, 0.5, 5000) == resample(tone, 123.25, 0.5, 5000));
    // Read from a later start, the slowed sound is the same one shifted.
    const std::vector<float> a = resample(tone, 1000, 0.5, 400), b = resample(tone, 1100, 0.5, 200);
    for (std::size_t i = 0; i < 200; ++i) CHECK(b[i] == doctest::Approx(a[i + 200]).epsilon(1e-4));
  }
}
