// The preview draws from the same camera the movie uses: at every frame time of camera.csv the
// preview's view has the same eye and look-at point, puts the look-at point in the middle of the
// picture, and spans the shared horizontal field of view.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "camera_interpolation.h"
#include "fixtures.h"
#include "shot.h"
#include "support.h"
#include "view.h"

using namespace bsim;
using bsim::test::bin;
using bsim::test::run_command;
using bsim::test::TempDir;

namespace {

// Every camera mode and interpolation window in one short shot.
const std::string kScene = test::fixtures::two_ball_scene(
    {"event 2 0.5 0.4   look   1.9 -1.2 1.0   1", "event 65535 0.6 0 hover  0 -2.3 2.4   0 0 0"});

struct CameraRow {
  int frame = 0;
  double time = 0;
  Vec3 eye, look;
  bool interpolating = false;
};

std::vector<CameraRow> read_camera_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "frame,time,cam_x,cam_y,cam_z,look_x,look_y,look_z,interpolating,replay");
  std::vector<CameraRow> rows;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string f[10];
    for (std::string& field : f) std::getline(fields, field, ',');
    rows.push_back({std::stoi(f[0]), std::stod(f[1]), Vec3(std::stod(f[2]), std::stod(f[3]), std::stod(f[4])),
                    Vec3(std::stod(f[5]), std::stod(f[6]), std::stod(f[7])), f[8] == "1"});
    CHECK(f[9] == "0");  // not a game: no replay
  }
  return rows;
}

}  // namespace

TEST_SUITE("preview camera") {
  TEST_CASE("the preview's view at every camera.csv frame is the exported camera") {
    TempDir dir;
    const std::string scene = dir.file("tour.scn", kScene);
    const auto out = dir.path / "out";
    const auto r = run_command(bin("billiards-export") + " " + scene + " --events-only --fps 24 -o " + out.string());
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::vector<CameraRow> rows = read_camera_csv((out / "camera.csv").string());
    const ShotResult loaded = load_shot(kScene, "tour");
    REQUIRE(loaded.shot);
    REQUIRE(rows.size() == static_cast<std::size_t>(std::llround(loaded.shot->timeline.duration() * 24)));
    int interpolating = 0;
    for (const CameraRow& row : rows) {
      const ViewCamera view = scripted_view(*loaded.shot, row.time);
      INFO("frame " << row.frame << " at t = " << row.time);
      CHECK((view.eye - row.eye).norm() < 1e-9);
      CHECK((view.target - row.look).norm() < 1e-9);
      CHECK(view.hfov_deg == kCameraFovDeg);
      interpolating += row.interpolating;
    }
    CHECK(interpolating > 0);  // the windows were exercised
  }

  TEST_CASE("the look-at point is the centre of the picture and the width spans the horizontal field of view") {
    ViewCamera view;
    view.eye = Vec3(-1.4, -0.9, 0.8);
    view.target = Vec3(0.3, 0.1, 0.0);
    const double width = 1280, height = 720, aspect = width / height;
    const Eigen::Matrix4f vp = projection_matrix(view, aspect) * view_matrix(view);
    double x = 0, y = 0;
    REQUIRE(project_to_pixels(vp, view.target, width, height, x, y));
    CHECK(x == doctest::Approx(width / 2).epsilon(1e-5));
    CHECK(y == doctest::Approx(height / 2).epsilon(1e-5));

    // A point at the edge of the horizontal field of view lands on the picture's right edge.
    const Vec3 forward = (view.target - view.eye).normalized();
    const Vec3 right = forward.cross(Vec3(0, 0, 1)).normalized();
    const double half = kCameraFovDeg * std::numbers::pi / 360;
    const Vec3 edge = view.eye + forward + right * std::tan(half);
    REQUIRE(project_to_pixels(vp, edge, width, height, x, y));
    CHECK(x == doctest::Approx(width).epsilon(1e-4));
    CHECK(y == doctest::Approx(height / 2).epsilon(1e-4));
    CHECK(vertical_fov_deg(kCameraFovDeg, aspect) < kCameraFovDeg);
  }

  TEST_CASE("looking straight down still gives a view") {
    ViewCamera view;
    view.eye = Vec3(0, 0, 3);
    view.target = Vec3(0, 0, 0);
    const Eigen::Matrix4f m = view_matrix(view);
    CHECK(m.allFinite());
    double x = 0, y = 0;
    REQUIRE(project_to_pixels(projection_matrix(view, 16.0 / 9.0) * m, Vec3(0, 0, 0), 160, 90, x, y));
    CHECK(x == doctest::Approx(80));
    CHECK(y == doctest::Approx(45));
  }
}
