// A game movie's captions in the develop stage: drawn only in the lower half of the picture, the
// same bytes every time (and a golden picture of one), the corner chosen away from the balls that
// matter, the frames folder's captions.txt read back as written, and each caption part of its frame's
// key in the frame store.
#include <doctest/doctest.h>

#include <algorithm>

#include "develop.h"
#include "frame_cache.h"
#include "frame_captions.h"
#include "golden.h"
#include "png_file.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

/// A picture with some structure: a ramp across, brighter towards the bottom.
HdrImage ramp(int width, int height) {
  HdrImage image{width, height, std::vector<float>(3 * static_cast<std::size_t>(width) * height)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.rgb[3 * (static_cast<std::size_t>(y) * width + x) + c] =
            0.05f + 0.4f * static_cast<float>(x) / static_cast<float>(width) +
            0.2f * static_cast<float>(y) / static_cast<float>(height) * static_cast<float>(c + 1) / 3.0f;
  return image;
}

/// A caption with everything it can show: an 8-ball rack part cleared, a foul that lost the game, the
/// winner, the replay.
FrameCaption full_caption(bool right = false) {
  FrameCaption f;
  Caption& c = f.caption;
  c.rules = RackGame::eight_ball;
  c.players = {"Ann", "Bo"};
  c.at_table = 1;
  c.shot = 11;
  for (int n = 1; n <= 15; ++n) c.rack.push_back(n);
  c.on_table = {1, 3, 8, 10, 11, 14};
  c.calls = {{CaptionCall::Kind::foul, "FOUL", "the 8 went down before the stripes were cleared"},
             {CaptionCall::Kind::winner, "WINNER", "Ann wins the game"}};
  c.replay = true;
  f.right = right;
  return f;
}

std::vector<std::uint8_t> developed(const HdrImage& image, const FrameCaption* caption) {
  std::vector<std::uint8_t> picture = develop(image);
  std::string error;
  if (caption) REQUIRE_MESSAGE(draw_lower_third(picture, image.width, image.height, *caption, error), error);
  return picture;
}

/// The first row in which the two pictures differ (height when they do not).
int first_differing_row(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int width, int height) {
  const std::size_t row = 3 * static_cast<std::size_t>(width);
  for (int y = 0; y < height; ++y)
    if (!std::equal(a.begin() + static_cast<std::ptrdiff_t>(y * row),
                    a.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                    b.begin() + static_cast<std::ptrdiff_t>(y * row)))
      return y;
  return height;
}

}  // namespace

TEST_SUITE("captions") {
  TEST_CASE("a caption is drawn low in the picture, never in its upper half, the same bytes every time") {
    std::string error;
    REQUIRE_MESSAGE(lower_third_fonts(error), error);
    for (const std::pair<int, int>& size : {std::pair{1280, 720}, std::pair{640, 360}, std::pair{320, 180}}) {
      const int width = size.first, height = size.second;
      CAPTURE(width);
      const HdrImage image = ramp(width, height);
      const std::vector<std::uint8_t> plain = developed(image, nullptr);
      for (const bool right : {false, true}) {
        const FrameCaption caption = full_caption(right);
        const std::vector<std::uint8_t> captioned = developed(image, &caption);
        const int row = first_differing_row(plain, captioned, width, height);
        CHECK(row >= height / 2);
        CHECK(row < height * 3 / 4);  // the panel and two calls reach well up into the lower half
        CHECK(developed(image, &caption) == captioned);
        // The corner: the caption's column only, the other side untouched.
        const CaptionBox column = lower_third_column(15, width, height, right);
        for (int y = height / 2; y < height; ++y)
          for (int x = 0; x < width; ++x)
            if (x < column.x0 || x >= column.x1)
              for (int c = 0; c < 3; ++c) {
                const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x) + c;
                if (plain[i] != captioned[i]) FAIL_CHECK("drawn outside its column at " << x << ", " << y);
              }
      }
    }
  }

  TEST_CASE("the panel leaves the middle of the picture clear, and a long name is cut short inside it") {
    std::string error;
    REQUIRE_MESSAGE(lower_third_fonts(error), error);
    for (const std::pair<int, int>& size : {std::pair{1280, 720}, std::pair{640, 360}}) {
      const int width = size.first, height = size.second;
      CAPTURE(width);
      // A shooter's view puts the cue ball low in the middle: clear of the panel in either corner, for
      // 9-ball's rack and 8-ball's.
      for (const int rack : {9, 15}) {
        CAPTURE(rack);
        CHECK(lower_third_column(rack, width, height, false).x1 < 0.46 * width);
        CHECK(lower_third_column(rack, width, height, true).x0 > 0.54 * width);
      }
      const HdrImage image = ramp(width, height);
      const std::vector<std::uint8_t> plain = developed(image, nullptr);
      FrameCaption caption = full_caption(false);
      caption.caption.players = {"Bartholomew Montgomery-Featherstonehaugh", "Bo"};
      caption.caption.at_table = 0;
      const std::vector<std::uint8_t> captioned = developed(image, &caption);
      const CaptionBox column = lower_third_column(15, width, height, false);
      for (int y = height / 2; y < height; ++y)
        for (int x = column.x1; x < width; ++x)
          for (int c = 0; c < 3; ++c) {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x) + c;
            if (plain[i] != captioned[i]) FAIL_CHECK("the name runs out of the panel at " << x << ", " << y);
          }
    }
  }

  TEST_CASE("a replay's tag is always shown: the calls below it are cut short to leave it room") {
    std::string error;
    REQUIRE_MESSAGE(lower_third_fonts(error), error);
    // The runs of the tags' red down the column's left edge: the FOUL tag's, and the REPLAY tag's above.
    const auto red_runs = [](const std::vector<std::uint8_t>& picture, int width, int height, int x) {
      int runs = 0;
      bool in_run = false;
      for (int y = height / 2; y < height; ++y) {
        const std::uint8_t* p = picture.data() + 3 * (static_cast<std::size_t>(y) * width + x);
        const bool red = p[0] == 204 && p[1] == 26 && p[2] == 34;
        runs += red && !in_run;
        in_run = red;
      }
      return runs;
    };
    for (const std::pair<int, int>& size : {std::pair{1280, 720}, std::pair{640, 360}, std::pair{320, 180}}) {
      const int width = size.first, height = size.second;
      CAPTURE(width);
      const HdrImage image = ramp(width, height);
      FrameCaption live = full_caption(false);
      live.caption.replay = false;
      const FrameCaption replay = full_caption(false);
      const int x = lower_third_column(15, width, height, false).x0 + 2;
      CHECK(red_runs(developed(image, &live), width, height, x) == 1);    // the foul
      CHECK(red_runs(developed(image, &replay), width, height, x) == 2);  // the foul and the replay
    }
  }

  TEST_CASE("golden: a captioned frame from the develop stage") {
    const HdrImage image = ramp(640, 360);
    const FrameCaption caption = full_caption();
    test::TempDir dir;
    const std::string png = (dir.path / "caption.png").string();
    std::string error;
    REQUIRE_MESSAGE(develop_to_png(image, png, error, &caption), error);
    const fs::path golden = test::golden_path("develop", "caption.png");
    if (test::updating_goldens()) test::write_golden(golden, test::require_file(png));
    REQUIRE_MESSAGE(fs::exists(golden), test::missing_golden_message(golden));
    CHECK_MESSAGE(test::require_file(png) == test::require_file(golden),
                  "the captioned frame differs from " << golden.string() << "; look at " << png);
  }

  TEST_CASE("captions.txt: each frame's caption read back as written, and part of its key in the frame store") {
    const FrameCaption a = full_caption();
    FrameCaption b = full_caption(true);
    b.caption.calls.clear();
    b.caption.replay = false;
    b.caption.players = {"Player 1", "Player\t2"};  // a tab cannot break the file
    test::TempDir dir;
    dir.file(kCaptionsName, captions_text({a, b}));
    const std::map<int, std::string> lines = read_caption_lines(dir.path.string());
    REQUIRE(lines.size() == 2);
    FrameCaption read;
    REQUIRE(parse_caption(lines.at(0), read));
    CHECK(read == a);
    REQUIRE(parse_caption(lines.at(1), read));
    b.caption.players[1] = "Player 2";
    CHECK(read == b);
    CHECK_FALSE(parse_caption("left\t9ball\t3\t0\tA\tB\t-\t-\t-", read));

    // Frame 2 has no caption: its key is as without the file; the others' keys hold their captions.
    const std::vector<std::uint64_t> plain = {1, 2, 3};
    std::vector<std::uint64_t> keys = plain;
    add_caption_keys(dir.path.string(), keys);
    CHECK(keys[0] != plain[0]);
    CHECK(keys[1] != plain[1]);
    CHECK(keys[2] == plain[2]);
    std::vector<std::uint64_t> same = {1, 1};
    add_caption_keys(dir.path.string(), same);
    CHECK(same[0] != same[1]);  // the same .pov under two captions: two pictures
  }

  TEST_CASE("a scene that is no game has no captions; a game's caption moves away from the cue ball") {
    const std::unique_ptr<Shot> plain =
        test::load_scene("ball 0 0 0\nball 1 0.5 0\ncue 0 0\nstroke 1 0 0 0\n", "plain");
    CHECK(frame_captions(*plain, movie_frame_moments(*plain, 30), 1280, 720).empty());

    ShotResult r = load_shot("game 9ball seed 2 shots 1\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n", "game");
    REQUIRE(r.shot);
    const Shot& shot = *r.shot;
    const Vec3 cue_ball = shot.timeline.motion_state(0, 0.0).position;
    REQUIRE(shot.scene.balls[0].number == 0);
    // A camera straight down 2 m over a point beside the cue ball: the ball is seen in the lower left
    // (then the lower right) of the picture, where the caption would be.
    const double half_w = 2.0 * CameraView(straight_down_camera(cue_ball, 2.0)).half_width();
    for (const double side : {1.0, -1.0}) {
      const Vec3 over = cue_ball + Vec3(side * 0.65 * half_w, 0.65 * half_w * 9.0 / 16.0, 0.0);
      std::vector<FrameMoment> moments = {{0.0, false, straight_down_camera(over, 2.0)}};
      const std::vector<FrameCaption> captions = frame_captions(shot, moments, 1280, 720);
      REQUIRE(captions.size() == 1);
      CAPTURE(side);
      CHECK(captions[0].right == (side > 0));
      CHECK(captions[0].caption.players == std::vector<std::string>{"Ann", "Bo"});
    }
  }
}
