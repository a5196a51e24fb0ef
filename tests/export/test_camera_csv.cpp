// camera.csv: the header, one row per frame, exact numbers that read back to the camera's pose.
#include <doctest/doctest.h>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"
#include "support.h"

using namespace bsim;

namespace {

const std::string kScene =
    "cue 0 0\n"
    "ball 0 -0.8 0 0.028575 0.6 0 0 1 0 0 0\n"
    "ball 1 0.3 0.4 0.028575 0 0 0 1 0 0 0\n"
    "camera\n"
    "event 0 0 0 hover -1.5 -1.5 1.2 0 0 0\n"
    "event 1 0.5 0.5 follow 0 -0.6 0 0.35\n"
    "event 65535 0.4 0 hover 1.5 1.5 1.5 0 0 0\n"
    "endcamera\n";

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

}  // namespace

TEST_SUITE("camera_csv") {
  TEST_CASE("one row per frame with the pose in shortest round-trip numbers") {
    ShotResult loaded = load_shot(kScene, "csv");
    REQUIRE(loaded.shot);
    const Shot& shot = *loaded.shot;
    const int fps = 24;
    std::ostringstream out;
    write_camera_csv(shot, fps, out);
    std::istringstream in(out.str());
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(line == "frame,time,cam_x,cam_y,cam_z,look_x,look_y,look_z,interpolating,replay");
    int rows = 0, inside = 0;
    while (std::getline(in, line)) {
      const std::vector<std::string> f = split(line);
      REQUIRE(f.size() == 10);
      CHECK(f[0] == std::to_string(rows));
      const double t = frame_time(rows, fps);
      CHECK(f[1] == format_number(t));
      const CameraPose pose = shot.camera->pose(t);
      for (int i = 0; i < 3; ++i) {
        CHECK(std::strtod(f[2 + i].c_str(), nullptr) == pose.location[i]);
        CHECK(std::strtod(f[5 + i].c_str(), nullptr) == pose.look_at[i]);
      }
      CHECK(f[8] == (pose.interpolating ? "1" : "0"));
      CHECK(f[9] == "0");  // not a game: no replay
      inside += pose.interpolating;
      ++rows;
    }
    CHECK(rows == frame_count(shot.timeline.duration(), fps));
    CHECK(inside > 0);
    CHECK(inside < rows);
    CHECK(out.str().back() == '\n');
  }

  TEST_CASE("the exporter writes camera.csv with --events-only, the same bytes each run") {
    test::TempDir dir;
    const std::string scene = dir.file("cam.scn", kScene);
    std::string first;
    for (int run = 0; run < 2; ++run) {
      const auto out = dir.path / ("out" + std::to_string(run));
      const test::CommandResult r = test::run_command(test::bin("billiards-export") + " '" + scene +
                                                      "' --events-only --fps 30 -o '" + out.string() + "'");
      REQUIRE_MESSAGE(r.exit_code == 0, r.err);
      const std::string text = test::require_file(out / "camera.csv");
      if (run == 0)
        first = text;
      else
        CHECK(text == first);
    }
    CHECK(first.rfind(
              "frame,time,cam_x,cam_y,cam_z,look_x,look_y,look_z,interpolating,replay\n0,0,-1.5,-1.5,1.2,0,0,0,0,0\n",
              0) == 0);
  }
}
