// The lens in the develop stage: the depth cast from the scene's geometry against distances worked by
// hand, the depth of field's occlusion (no halo round a sharp foreground, a blurred foreground spread
// over a sharp background), the sensor's grain (its own in every frame, the same on every run), the
// lateral chromatic aberration (half a pixel at most at the corners), the vignetting wide open, and
// lens.txt: read back as written, and part of each frame's key.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numeric>

#include "depth_of_field.h"
#include "depth_scene.h"
#include "develop.h"
#include "frame_cache.h"
#include "frame_lens.h"
#include "pocket_fall.h"
#include "scene.h"
#include "support.h"
#include "table.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

/// The standard table's scene (the physics' ball).
Scene standard_scene() {
  Scene scene;
  scene.rails = standard_rails();
  scene.pockets = standard_pockets();
  return scene;
}

/// The depth at the centre of an odd-sized picture (its pixel's ray is the camera's axis).
constexpr int kW = 101, kH = 57;
double centre_depth(const DepthScene& scene, const DepthMoving& moving, const Vec3& eye, const Vec3& look) {
  const DepthPicture d =
      cast_depth(scene, moving, CameraView({eye, look, false}, kCameraFovDeg, double(kW) / kH), kW, kH);
  return d.depth[static_cast<std::size_t>(kH / 2) * kW + kW / 2];
}

HdrImage uniform(int width, int height, float value) {
  return {width, height, std::vector<float>(3 * static_cast<std::size_t>(width) * height, value)};
}

float* pixel(HdrImage& image, int x, int y) {
  return image.rgb.data() + 3 * (static_cast<std::size_t>(y) * image.width + x);
}
const float* pixel(const HdrImage& image, int x, int y) {
  return image.rgb.data() + 3 * (static_cast<std::size_t>(y) * image.width + x);
}

/// A frame's lens: the camera 1.2 m from the table's middle, low over the bed, focused 0.8 m away.
FrameLens close_frame(int number) {
  FrameLens f;
  f.frame = number;
  f.pose = {Vec3(-1.2, 0, 0.25), Vec3(0, 0, 0.03), false};
  f.lens = {focal_length_mm(kCameraFovDeg), 2.8, 0.8};
  f.moving.balls = {Vec3(-0.4, 0, 0.028575), Vec3(0.6, 0.1, 0.028575)};
  return f;
}

/// A picture with detail everywhere: stripes and a few bright points.
HdrImage test_picture(int width, int height) {
  HdrImage image = uniform(width, height, 0.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) pixel(image, x, y)[c] = 0.05f + 0.3f * static_cast<float>((x / 3 + y / 5 + c) % 2);
  pixel(image, width / 3, height / 4)[0] = 30.0f;
  return image;
}

}  // namespace

TEST_SUITE("lens develop") {
  TEST_CASE("the depth is the distance along the camera's axis to the core's geometry") {
    const Scene table = standard_scene();
    const DepthScene scene = depth_scene(table);
    const double r = table.physics.ball_radius;
    DepthMoving none;
    // A ball 1 m ahead of the camera, level with its centre: its front 1 - R away.
    DepthMoving ball;
    ball.balls = {Vec3(0, 0, r)};
    CHECK(centre_depth(scene, ball, Vec3(-1, 0, r), Vec3(0, 0, r)) == doctest::Approx(1 - r).epsilon(1e-6));
    // The bed 1 m below a camera looking straight down: 1 m at every pixel (the bed square to the axis).
    const DepthPicture down = cast_depth(
        scene, none, CameraView({Vec3(0.5, 0.3, 1), Vec3(0.5, 0.3, 0), false}, kCameraFovDeg, 16.0 / 9), 64, 36);
    for (const float d : down.depth) CHECK(d == doctest::Approx(1.0).epsilon(1e-6));
    // The far long cushion's nose (y = 0.635, at the nose height), seen level from the table's middle;
    // below the nose its face slopes back to its foot, 13.5 mm behind.
    const double nose = kStandardTable.nose_height;
    CHECK(centre_depth(scene, none, Vec3(0.3, 0, nose), Vec3(0.3, 1, nose)) == doctest::Approx(0.635).epsilon(1e-6));
    const DepthPicture level = cast_depth(
        scene, none, CameraView({Vec3(0.3, 0, nose), Vec3(0.3, 1, nose), false}, kCameraFovDeg, 1.0), 101, 101);
    const float face = level.depth[55 * 101 + 50];
    CHECK(face > 0.635f);
    CHECK(face < 0.635f + 0.0135f);
    // Straight down into a corner pocket: through its hole to the cup's floor.
    const Vec3 hole = table.pockets[0].center;
    CHECK(centre_depth(scene, none, hole + Vec3(0, 0, 1), hole) ==
          doctest::Approx(1 + kPocketDepth + 0.0005).epsilon(1e-6));
    // Straight up from over the middle: the lamp's shade 1.05 m above the bed.
    CHECK(centre_depth(scene, none, Vec3(0, 0, 0.5), Vec3(0, 0, 1.5)) ==
          doctest::Approx(kRoom.lamp.bottom - 0.5).epsilon(1e-6));
    // Level over the lamp towards +x: the room's wall, 3.5 m beyond the table's outer edge (1.45 m).
    CHECK(centre_depth(scene, none, Vec3(0, 0, 1.5), Vec3(1, 0, 1.5)) == doctest::Approx(4.95).epsilon(1e-6));
    // The stick across the view 0.7 m ahead, 0.3 m from its tip: its near side, its radius there short of it.
    DepthMoving stick;
    stick.stick = CuePose{Vec3(-0.3, 0.2, r), Vec3(1, 0, 0), true};
    const double radius = kCueTipRadius + (kCueButtRadius - kCueTipRadius) * 0.3 / kCueLength;
    CHECK(centre_depth(scene, stick, Vec3(0, -0.5, r), Vec3(0, 0, r)) == doctest::Approx(0.7 - radius).epsilon(1e-6));
  }

  TEST_CASE("lens.txt reads back as written; a line that is not a lens is refused") {
    const DepthScene scene = depth_scene(standard_scene());
    DepthScene read;
    std::string error;
    REQUIRE_MESSAGE(parse_depth_scene(depth_scene_text(scene), read, error), error);
    CHECK(depth_scene_text(read) == depth_scene_text(scene));
    CHECK(read.solids.size() == scene.solids.size());
    CHECK_FALSE(parse_depth_scene("ball 0.03\nroom 0 0 0 1 1 1\nsolid 1 2\n", read, error));
    CHECK(error == "line 3 is not part of a scene: solid 1 2");

    test::TempDir dir;
    FrameLens f = close_frame(7);
    f.moving.stick = CuePose{Vec3(0.1, 0.2, 0.03), Vec3(-1, 0, 0), true};
    dir.file(kLensName, lens_text(scene, {close_frame(6), f}));
    const LensFile file = read_lens_file(dir.path.string());
    REQUIRE(file.frames.size() == 2);
    REQUIRE_MESSAGE(parse_depth_scene(file.scene, read, error), error);
    FrameLens back;
    REQUIRE(parse_frame_lens(file.frames.at(7), back));
    CHECK(back.frame == 7);
    CHECK(back.pose.location == f.pose.location);
    CHECK(back.lens.focus == f.lens.focus);
    CHECK(back.lens.aperture == f.lens.aperture);
    CHECK(back.moving.balls == f.moving.balls);
    REQUIRE(back.moving.stick);
    CHECK(back.moving.stick->tip == f.moving.stick->tip);
    REQUIRE(parse_frame_lens(file.frames.at(6), back));
    CHECK_FALSE(back.moving.stick);
    CHECK_FALSE(parse_frame_lens("frame 3 camera 1 2 3", back));
    CHECK_FALSE(parse_frame_lens(file.frames.at(7) + " 4", back));
  }

  TEST_CASE("a frame's lens, focus and number are part of its key in the frame store") {
    const DepthScene scene = depth_scene(standard_scene());
    test::TempDir dir;
    const std::vector<std::uint64_t> bare(3, 42);
    std::vector<std::uint64_t> keys = bare;
    add_lens_keys(dir.path.string(), keys);
    CHECK(keys == bare);  // no lens.txt: the keys as they were
    FrameLens a = close_frame(0), b = close_frame(1), c = close_frame(2);
    dir.file(kLensName, lens_text(scene, {a, b, c}));
    add_lens_keys(dir.path.string(), keys);
    CHECK(keys[0] != bare[0]);
    CHECK(keys[0] != keys[1]);  // the same picture, but each frame has its grain
    c.lens.focus = 0.9;
    dir.file(kLensName, lens_text(scene, {a, b, c}));
    std::vector<std::uint64_t> refocused = bare;
    add_lens_keys(dir.path.string(), refocused);
    CHECK(refocused[0] == keys[0]);
    CHECK(refocused[2] != keys[2]);
  }

  TEST_CASE("no halo: a sharp foreground disc over a blurred background keeps its edge") {
    // Green stripes 4 m away, blurred by 8 pixels; a red disc 1 m away, sharp.
    const int w = 96, h = 64;
    HdrImage image = uniform(w, h, 0.0f);
    DepthPicture depth{w, h, std::vector<float>(static_cast<std::size_t>(w) * h, 4.0f)};
    std::vector<float> radii(depth.depth.size(), 8.0f);
    const auto in_disc = [](int x, int y) { return (x - 48) * (x - 48) + (y - 32) * (y - 32) < 15 * 15; };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (in_disc(x, y)) {
          pixel(image, x, y)[0] = 0.8f;
          depth.depth[static_cast<std::size_t>(y) * w + x] = 1.0f;
          radii[static_cast<std::size_t>(y) * w + x] = 0.0f;
        } else {
          pixel(image, x, y)[1] = (x / 2) % 2 ? 0.9f : 0.1f;
        }
      }
    const HdrImage before = image;
    gather_blur(image, depth, radii);
    int outside = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        CAPTURE(x);
        CAPTURE(y);
        if (in_disc(x, y)) {
          // Every pixel of the disc, its edge too, exactly as it was: no background light over it.
          for (int c = 0; c < 3; ++c) CHECK(pixel(image, x, y)[c] == pixel(before, x, y)[c]);
        } else {
          // No red round it, and the stripes blurred to their mean.
          CHECK(pixel(image, x, y)[0] == 0.0f);
          if (x > 4 && x < w - 5 && !in_disc(x - 12, y) && !in_disc(x + 12, y)) {
            CHECK(pixel(image, x, y)[1] == doctest::Approx(0.5f).epsilon(0.15));
            ++outside;
          }
        }
      }
    CHECK(outside > 1000);
  }

  TEST_CASE("a blurred foreground spreads over a sharp background, without a step at its edge") {
    // A red half-plane 0.5 m away blurred by 10 pixels (x < 48) over a sharp green one 2 m away.
    const int w = 96, h = 48;
    HdrImage image = uniform(w, h, 0.0f);
    DepthPicture depth{w, h, std::vector<float>(static_cast<std::size_t>(w) * h, 2.0f)};
    std::vector<float> radii(depth.depth.size(), 0.0f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool near = x < 48;
        pixel(image, x, y)[near ? 0 : 1] = 1.0f;
        depth.depth[static_cast<std::size_t>(y) * w + x] = near ? 0.5f : 2.0f;
        radii[static_cast<std::size_t>(y) * w + x] = near ? 10.0f : 0.0f;
      }
    gather_blur(image, depth, radii);
    const int y = h / 2;
    // The red reaches over the green up to about its radius, fading; at the edge about half of each.
    CHECK(pixel(image, 48, y)[0] == doctest::Approx(0.5f).epsilon(0.25));
    CHECK(pixel(image, 47, y)[0] == doctest::Approx(0.5f).epsilon(0.25));
    CHECK(pixel(image, 52, y)[0] > 0.05f);
    CHECK(pixel(image, 60, y)[0] == 0.0f);
    CHECK(pixel(image, 30, y)[0] == doctest::Approx(1.0f).epsilon(1e-5));
    float previous = 1.0f;
    for (int x = 30; x < 62; ++x) {
      CAPTURE(x);
      const float red = pixel(image, x, y)[0];
      CHECK(red <= previous + 1e-6f);  // falling all the way across
      CHECK(previous - red < 0.1f);    // and never by a step
      previous = red;
    }
  }

  TEST_CASE("a picture all in focus is left exactly as it was") {
    HdrImage image = test_picture(64, 40);
    const HdrImage before = image;
    const DepthPicture depth{64, 40, std::vector<float>(64 * 40, 1.0f)};
    gather_blur(image, depth, std::vector<float>(64 * 40, 0.25f));
    CHECK(image.rgb == before.rgb);
  }

  TEST_CASE("developing through the lens is deterministic; the grain is each frame's own") {
    const DepthScene scene = depth_scene(standard_scene());
    const HdrImage image = test_picture(160, 90);
    const FrameLens five = close_frame(5), six = close_frame(6);
    const std::vector<std::uint8_t> a = develop(image, {&five, &scene}), b = develop(image, {&five, &scene});
    CHECK(a == b);
    const std::vector<std::uint8_t> other = develop(image, {&six, &scene});
    CHECK(other != a);
    CHECK(develop(image) != a);  // the lens changes the picture
    // The grain itself: as strong as the model says, and a new pattern in each frame.
    const HdrImage grey = uniform(320, 180, 0.2f);
    HdrImage g5 = grey, g6 = grey, again = grey;
    add_grain(g5, 5);
    add_grain(g6, 6);
    add_grain(again, 5);
    CHECK(g5.rgb == again.rgb);
    double sum = 0, squares = 0, cross = 0;
    for (std::size_t i = 0; i < g5.rgb.size(); ++i) {
      const double n5 = g5.rgb[i] - 0.2, n6 = g6.rgb[i] - 0.2;
      sum += n5;
      squares += n5 * n5;
      cross += n5 * n6;
    }
    const double n = static_cast<double>(g5.rgb.size()), sigma = std::sqrt(kGrainShot * 0.2 + kGrainFloor);
    CHECK(std::abs(sum / n) < 0.01 * sigma);
    CHECK(std::sqrt(squares / n) == doctest::Approx(sigma).epsilon(0.02));
    CHECK(std::abs(cross / squares) < 0.01);  // the two frames' noise is unrelated
  }

  TEST_CASE("lateral chromatic aberration: at most half a pixel at the corners of a 1280x720 picture") {
    CHECK(chromatic_shift(0, 0, 1280, 720, true) <= 0.5);
    CHECK(chromatic_shift(0, 0, 1280, 720, true) > 0.4);
    CHECK(chromatic_shift(1280, 720, 1280, 720, false) < 0);
    CHECK(chromatic_shift(1280, 720, 1280, 720, false) >= -0.5);
    CHECK(chromatic_shift(640, 360, 1280, 720, true) == 0.0);
    // In proportion to the size: a quarter as many pixels at 320x180.
    CHECK(chromatic_shift(0, 0, 320, 180, true) == doctest::Approx(chromatic_shift(0, 0, 1280, 720, true) / 4));
    // On a picture: a white point near the bottom-right corner; its red moves out, its blue in.
    HdrImage image = uniform(1280, 720, 0.0f);
    for (int y = 708; y < 711; ++y)
      for (int x = 1268; x < 1271; ++x) std::fill_n(pixel(image, x, y), 3, 1.0f);
    chromatic_aberration(image);
    double cx[3] = {0, 0, 0}, mass[3] = {0, 0, 0};
    for (int y = 700; y < 720; ++y)
      for (int x = 1260; x < 1280; ++x)
        for (int c = 0; c < 3; ++c) {
          cx[c] += (x + 0.5) * pixel(image, x, y)[c];
          mass[c] += pixel(image, x, y)[c];
        }
    const double red = cx[0] / mass[0] - cx[1] / mass[1], blue = cx[2] / mass[2] - cx[1] / mass[1];
    CHECK(cx[1] / mass[1] == doctest::Approx(1269.5));  // green stays
    CHECK(red > 0.3);
    CHECK(red < 0.5);
    CHECK(blue < -0.1);
    CHECK(blue > -0.5);
  }

  TEST_CASE("vignetting wide open darkens the corners more; stopped down it is the cos^4 law alone") {
    const float cos4 = vignette(0, 0, 1281, 721);
    CHECK(vignette(0, 0, 1281, 721, kClearVignetteAperture) == cos4);
    CHECK(vignette(0, 0, 1281, 721, 11.0) == cos4);
    CHECK(vignette(0, 0, 1281, 721, kOpenAperture) == doctest::Approx(cos4 * (1 - kOpenVignette)).epsilon(0.003));
    CHECK(vignette(0, 0, 1281, 721, 4.0) > vignette(0, 0, 1281, 721, kOpenAperture));
    CHECK(vignette(640, 360, 1281, 721, kOpenAperture) == doctest::Approx(1.0).epsilon(1e-6));
  }
}
