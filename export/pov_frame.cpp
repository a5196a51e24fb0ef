#include "pov_frame.h"

#include <cmath>
#include <cstdio>

#include "camera_interpolation.h"
#include "frames.h"
#include "pov_format.h"
#include "pov_table.h"
#include "shot.h"

namespace bsim {

namespace {

/// A POV-Ray `matrix`: the images of x, y and z, then the translation.
std::string pov_matrix(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& at) {
  std::string text = "matrix <";
  const Vec3* rows[] = {&x, &y, &z, &at};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 3; ++c) text += (r || c ? ", " : "") + pov_number((*rows[r])[c]);
  }
  return text + ">";
}

/// POV-Ray cannot orient a camera looking along its sky vector (z). A camera on its look point (closer
/// than the files' micrometre) is the straight-down camera, 1 m over its look point; a view that the
/// core counts as vertical (picture_up() is +y) is turned a hair towards +y so that POV-Ray puts the
/// table's +y at the top of its picture, as the preview does.
void steady_camera(Vec3& location, Vec3& look_at) {
  if ((look_at - location).norm() < 1e-6) look_at = location + straight_down();
  const Vec3 d = look_at - location;
  if (picture_up(d) == Vec3::UnitY()) look_at = location + d.norm() * Vec3(0, 1e-4, d.z() > 0 ? 1 : -1);
}

}  // namespace

std::string frame_name(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d", frame);
  return name;
}

void write_pov_frame(const Shot& shot, int frame, int fps, std::ostream& out) {
  const double t = frame_time(frame, fps);
  out << "// " << frame_name(frame) << " of " << shot.scene.name << ": t = " << pov_number(t) << " s\n";
  out << "#version 3.7;\n#include \"" << kPovIncludeName << "\"\n\n";

  const CameraPose camera = shot.camera->pose(t);
  Vec3 location = camera.location, look_at = camera.look_at;
  steady_camera(location, look_at);
  // right is -x for z-up right-handed coordinates; angle is the horizontal field of view.
  out << "camera {\n  perspective\n  location " << pov_vector(location) << "\n  sky z\n  up z\n"
      << "  right -x * image_width / image_height\n  angle " << pov_number(kCameraFovDeg) << "\n  look_at "
      << pov_vector(look_at) << "\n}\n\n";

  for (int i = 0; i < shot.timeline.ball_count(); ++i) {
    const BallState state = shot.timeline.state(i, t);
    if (state.motion == Motion::pocketed) continue;  // at rest in its pocket, out of sight
    const Eigen::Matrix3d r = state.orientation.normalized().toRotationMatrix();
    const int number = shot.scene.balls[static_cast<std::size_t>(i)].number;
    out << "object { Ball(" << number << ") " << pov_matrix(r.col(0), r.col(1), r.col(2), state.position)
        << " }  // ball " << i << "\n";
  }

  const CuePose cue = shot.cue->pose(t);
  if (cue.visible) {
    const Vec3 along = cue.axis.normalized();
    Vec3 side = Vec3::UnitZ().cross(along);
    if (side.norm() < 1e-9) side = Vec3::UnitY();
    side.normalize();
    const Vec3 up = along.cross(side);
    out << "object { CueStick " << pov_matrix(along, side, up, cue.tip) << " }\n";
  }
}

}  // namespace bsim
