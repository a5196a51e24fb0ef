// The develop stage: POV-Ray's linear .hdr to the movie's 8-bit sRGB PNG, step by step on small
// synthetic pictures, and the whole of it on files.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numeric>

#include <stb_image_write.h>

#include "develop.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

HdrImage uniform(int width, int height, float value) {
  return {width, height, std::vector<float>(3 * static_cast<std::size_t>(width) * height, value)};
}

float& red(HdrImage& image, int x, int y) { return image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x)]; }

double total(const HdrImage& image) { return std::accumulate(image.rgb.begin(), image.rgb.end(), 0.0); }

/// The sRGB encoding with the standard's pow (IEC 61966-2-1), the reference for the bisection's.
double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

/// A picture with a smooth ramp and a few over-bright points, written as a Radiance .hdr.
std::string write_test_hdr(const test::TempDir& dir, const std::string& name) {
  HdrImage image = uniform(96, 54, 0.0f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x) + c] = 0.01f * static_cast<float>(x + c * y);
  red(image, 20, 20) = 40.0f;
  red(image, 70, 30) = 8.0f;
  const std::string path = (dir.path / name).string();
  REQUIRE(stbi_write_hdr(path.c_str(), image.width, image.height, 3, image.rgb.data()));
  return path;
}

}  // namespace

TEST_SUITE("develop") {
  TEST_CASE("the tone curve is monotone, maps 0 to 0 and rolls highlights off instead of clipping them") {
    CHECK(tone_curve(0.0f) == 0.0f);
    CHECK(tone_curve(-1.0f) == 0.0f);
    CHECK(tone_curve(NAN) == 0.0f);
    float previous = 0.0f;
    for (float x = 0.001f; x < kToneWhite; x *= 1.05f) {
      const float y = tone_curve(x);
      CAPTURE(x);
      CHECK(y > previous);
      CHECK(y < 1.0f);
      previous = y;
    }
    CHECK(tone_curve(kToneWhite) == 1.0f);
    CHECK(tone_curve(1e6f) == 1.0f);
    // The shoulder: each doubling of light above white gains less than the one before.
    CHECK(tone_curve(4.0f) - tone_curve(2.0f) < tone_curve(2.0f) - tone_curve(1.0f));
    CHECK(tone_curve(8.0f) - tone_curve(4.0f) < 0.5f * (tone_curve(2.0f) - tone_curve(1.0f)));
    // Light twice as bright as the old clipping point is still told from white.
    CHECK(tone_curve(2.0f) < 0.95f);
  }

  TEST_CASE("the film's colour draws colours towards their luma, keeping greys and the luma") {
    float r = 0.4f, g = 0.4f, b = 0.4f;
    saturate(r, g, b);
    CHECK(r == doctest::Approx(0.4f));
    CHECK(g == doctest::Approx(0.4f));
    CHECK(b == doctest::Approx(0.4f));
    // The cloth's green: its luma stays, its red and blue rise towards it, its green falls.
    const float r0 = 0.02f, g0 = 0.25f, b0 = 0.08f;
    r = r0, g = g0, b = b0;
    saturate(r, g, b);
    const float luma = 0.2126f * r0 + 0.7152f * g0 + 0.0722f * b0;
    CHECK(0.2126f * r + 0.7152f * g + 0.0722f * b == doctest::Approx(luma));
    CHECK(r == doctest::Approx(luma + kSaturation * (r0 - luma)));
    CHECK(g == doctest::Approx(luma + kSaturation * (g0 - luma)));
    CHECK(kSaturation < 1.0f);
    CHECK(r > r0);
    CHECK(g < g0);
    // A pure colour never goes below black.
    r = 0.0f, g = 0.0f, b = 1.0f;
    saturate(r, g, b);
    CHECK(r >= 0.0f);
    CHECK(g >= 0.0f);
  }

  TEST_CASE("the 8-bit sRGB encoding rounds to the nearest code of the standard's curve") {
    CHECK(encode_srgb8(0.0f) == 0);
    CHECK(encode_srgb8(1.0f) == 255);
    CHECK(encode_srgb8(2.0f) == 255);
    CHECK(encode_srgb8(0.18f) == 118);  // 0.4614 x 255
    CHECK(encode_srgb8(0.5f) == 188);   // 0.7354 x 255
    for (int i = 0; i <= 2000; ++i) {
      const float linear = static_cast<float>(i) / 2000.0f;
      const double exact = 255.0 * srgb_encode(linear);
      if (std::abs(exact - std::floor(exact) - 0.5) < 1e-4) continue;  // a tie within float precision
      CAPTURE(linear);
      CHECK(encode_srgb8(linear) == static_cast<int>(std::lround(exact)));
    }
  }

  TEST_CASE("vignetting darkens the corners by the cos^4 law and leaves the centre") {
    const double corner = std::pow(std::cos(20.0 * M_PI / 180.0), 4.0);  // 0.78
    CHECK(vignette(640, 360, 1281, 721) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(vignette(0, 0, 1281, 721) == doctest::Approx(corner).epsilon(0.002));
    CHECK(vignette(1280, 720, 1281, 721) == doctest::Approx(corner).epsilon(0.002));
    // Halfway to the corner: tan is half the corner's, so cos^4 = 1 / (1 + tan^2)^2.
    const double half_tan = 0.5 * std::tan(20.0 * M_PI / 180.0);
    CHECK(vignette(320, 180, 1281, 721) ==
          doctest::Approx(1.0 / std::pow(1.0 + half_tan * half_tan, 2.0)).epsilon(0.003));
    // expose() applies it, with the exposure, to every pixel.
    HdrImage image = uniform(33, 19, 0.5f);
    expose(image);
    CHECK(red(image, 16, 9) == doctest::Approx(0.5 * kExposure).epsilon(1e-6));
    CHECK(red(image, 0, 0) == doctest::Approx(0.5 * kExposure * vignette(0, 0, 33, 19)).epsilon(1e-6));
    CHECK(red(image, 0, 0) < red(image, 8, 4));
  }

  TEST_CASE("a bright point blooms into a soft halo, keeping its light; a dim picture gets none") {
    HdrImage dim = uniform(128, 72, 0.0f);
    for (std::size_t i = 0; i < dim.rgb.size(); ++i) dim.rgb[i] = kGlareThreshold * static_cast<float>(i % 97) / 97.0f;
    const HdrImage dim_before = dim;
    add_glare(dim);
    CHECK(dim.rgb == dim_before.rgb);

    HdrImage image = uniform(128, 72, 0.1f);
    red(image, 64, 36) = 100.0f;
    const HdrImage before = image;
    add_glare(image);
    // The halo falls off with the distance from the point, and far away nothing changes.
    const float near = red(image, 66, 36) - 0.1f, mid = red(image, 70, 36) - 0.1f, far = red(image, 76, 36) - 0.1f;
    CHECK(near > mid);
    CHECK(mid > far);
    CHECK(far > 0.0f);
    CHECK(red(image, 2, 2) == doctest::Approx(0.1f).epsilon(1e-3));
    // The point keeps most of its light: glare is a halo, not a smear.
    CHECK(red(image, 64, 36) > 0.75f * 100.0f);
    CHECK(red(image, 64, 36) < 100.0f);
    // Only red was bright: the halo keeps the point's hue, red.
    CHECK(image.rgb[3 * (36 * 128 + 66) + 1] - 0.1f < 0.01f * near);
    // Energy kept: what left the point lies round it (the halo stays well inside the picture).
    CHECK(total(image) == doctest::Approx(total(before)).epsilon(1e-3));

    // Odd and tiny sizes (a padded --size, CI's drafts) work the same way.
    for (const auto& [w, h] : {std::pair{33, 19}, std::pair{3, 1}, std::pair{1, 1}}) {
      HdrImage odd = uniform(w, h, 0.1f);
      red(odd, w / 2, h / 2) = 50.0f;
      const double light = total(odd);
      add_glare(odd);
      CHECK(total(odd) <= light * (1.0 + 1e-5));
      CHECK(total(odd) > 0.8 * light);
    }
  }

  TEST_CASE("developing is deterministic: the same .hdr gives the same PNG bytes") {
    test::TempDir dir;
    const std::string hdr = write_test_hdr(dir, "frame.hdr");
    HdrImage read;
    std::string error;
    REQUIRE_MESSAGE(read_hdr(hdr, read, error), error);
    CHECK(read.width == 96);
    CHECK(read.height == 54);
    CHECK(red(read, 20, 20) == doctest::Approx(40.0f).epsilon(0.01));  // light above 1 survives the file
    CHECK(develop(read) == develop(read));

    const std::string a = (dir.path / "a.png").string(), b = (dir.path / "b.png").string();
    REQUIRE_MESSAGE(develop_file(hdr, a, error), error);
    REQUIRE_MESSAGE(develop_file(hdr, b, error), error);
    CHECK(test::require_file(a) == test::require_file(b));
    CHECK(test::require_file(a).substr(1, 3) == "PNG");
  }

  TEST_CASE("a missing, corrupt or non-Radiance .hdr is a clear error naming the file") {
    test::TempDir dir;
    HdrImage image;
    std::string error;
    const std::string missing = (dir.path / "missing.hdr").string();
    CHECK_FALSE(read_hdr(missing, image, error));
    CHECK(error.find("cannot read " + missing + ": ") == 0);

    const std::string garbage = dir.file("garbage.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X nonsense\n");
    error.clear();
    CHECK_FALSE(read_hdr(garbage, image, error));
    CHECK(error == "cannot read " + garbage + ": no resolution line of the form -Y HEIGHT +X WIDTH");

    // Cut short, as by a full disk: said so (stb_image's reader would loop for ever here).
    const std::string whole = test::require_file(write_test_hdr(dir, "whole.hdr"));
    const std::string cut = dir.file("cut.hdr", whole.substr(0, whole.size() / 2));
    error.clear();
    CHECK_FALSE(read_hdr(cut, image, error));
    CHECK(error == "cannot read " + cut + ": truncated");

    const std::string text = dir.file("text.hdr", "not a picture at all\n");
    error.clear();
    CHECK_FALSE(develop_file(text, (dir.path / "out.png").string(), error));
    CHECK(error == "cannot read " + text + ": not a Radiance .hdr picture");
    CHECK_FALSE(fs::exists(dir.path / "out.png"));

    // A PNG where the .hdr should be: stb_image would make up linear light from it, so it is refused.
    const std::string hdr = write_test_hdr(dir, "frame.hdr"), png = (dir.path / "frame.png").string();
    REQUIRE_MESSAGE(develop_file(hdr, png, error), error);
    error.clear();
    CHECK_FALSE(read_hdr(png, image, error));
    CHECK(error == "cannot read " + png + ": not a Radiance .hdr picture");

    // A PNG that cannot be written names it, and leaves nothing.
    const std::string nowhere = (dir.path / "no-such-dir" / "out.png").string();
    error.clear();
    CHECK_FALSE(develop_file(hdr, nowhere, error));
    CHECK(error.find("cannot write " + nowhere + ": ") == 0);
    CHECK_FALSE(fs::exists(nowhere));
  }
}
