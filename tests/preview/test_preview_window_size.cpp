// The interactive window's default size fits the screen: 1280x720 pictures on a large screen,
// smaller at the same 16:9 on a small one (a 1366x768 laptop), with the controls and a title bar.
#include <doctest/doctest.h>

#include <string>

#include <stb_image.h>

#include "fixtures.h"
#include "support.h"
#include "viewer_ui.h"

using namespace bsim;
using bsim::test::quoted;

namespace {

/// Whether a window showing `picture` fits a work area of width x height with its decorations.
bool fits(PictureSize picture, int width, int height) {
  return picture.width + kDecorationsWidth <= width && picture.height + kControlsHeight + kDecorationsHeight <= height;
}

}  // namespace

TEST_SUITE("preview window size") {
  TEST_CASE("the default picture: 1280x720 when it fits, else smaller at 16:9") {
    const PictureSize large = default_window_picture(1920, 1040);
    CHECK(large.width == 1280);
    CHECK(large.height == 720);
    for (const auto& screen : {std::pair{1366, 768}, std::pair{1366, 728}, std::pair{1280, 800}, std::pair{1024, 768},
                               std::pair{800, 600}}) {
      const int w = screen.first, h = screen.second;  // plain names: CAPTURE cannot take a binding
      CAPTURE(w);
      CAPTURE(h);
      const PictureSize p = default_window_picture(w, h);
      CHECK(fits(p, w, h));
      CHECK(p.width * 9 == doctest::Approx(p.height * 16).epsilon(0.01));
      CHECK(p.height < 720);
    }
    const PictureSize laptop = default_window_picture(1366, 728);  // 1366x768 less a 40 px task bar
    CHECK(laptop.height == 728 - kControlsHeight - kDecorationsHeight);
    const PictureSize tiny = default_window_picture(300, 200);  // never below 320x180
    CHECK(tiny.width == 320);
    CHECK(tiny.height == 180);
  }

  TEST_CASE("without a work area: a fixed default that fits 1366x768 with a task bar") {
    const PictureSize fallback = default_window_picture(0, 0);
    CHECK(fallback.width == 768);
    CHECK(fallback.height == 432);
    CHECK(fits(fallback, 1366, 768 - 40));
  }

  TEST_CASE("under Xvfb on a 1366x768 screen the window without --size fits it; --size still sets it") {
    test::require_program("xvfb-run");
    test::require_program("xauth");
    test::TempDir dir;
    const std::string scene = dir.file("two.scn", test::fixtures::two_ball_scene());
    const std::string shot = (dir.path / "window.png").string();
    auto run = [&](const std::string& size) {
      return test::run_command("xvfb-run -a -s '-screen 0 1366x768x24' " + quoted(test::bin("billiards-preview")) +
                               " " + quoted(scene) + size + " --quit-after 0.5 --screenshot " + quoted(shot));
    };
    auto screenshot_size = [&]() {
      int width = 0, height = 0, channels = 0;
      REQUIRE(stbi_info(shot.c_str(), &width, &height, &channels));
      return PictureSize{width, height};
    };
    const test::CommandResult fitted = run("");
    INFO(fitted.err);
    REQUIRE(fitted.exit_code == 0);
    const PictureSize window = screenshot_size();
    CHECK(window.width + kDecorationsWidth <= 1366);
    CHECK(window.height + kDecorationsHeight <= 768);
    CHECK(window.height - kControlsHeight == default_window_picture(1366, 768).height);

    REQUIRE(run(" --size 480x270").exit_code == 0);
    const PictureSize sized = screenshot_size();
    CHECK(sized.width == 480);
    CHECK(sized.height == 270 + kControlsHeight);
  }
}
