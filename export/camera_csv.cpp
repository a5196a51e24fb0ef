// camera.csv: where the camera is and what it looks at in every frame (format in the README).
#include <string>

#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"

namespace bsim {

void write_camera_csv(const Shot& shot, int fps, std::ostream& out) {
  out << "frame,time,cam_x,cam_y,cam_z,look_x,look_y,look_z,interpolating\n";
  const int frames = frame_count(shot.timeline.duration(), fps);
  std::string row;
  for (int k = 0; k < frames; ++k) {
    const double t = frame_time(k, fps);
    const CameraPose pose = shot.camera->pose(t);
    row = std::to_string(k);
    row += ',';
    append_number(row, t);
    for (int i = 0; i < 3; ++i) {
      row += ',';
      append_number(row, pose.location[i]);
    }
    for (int i = 0; i < 3; ++i) {
      row += ',';
      append_number(row, pose.look_at[i]);
    }
    row += pose.interpolating ? ",1\n" : ",0\n";
    out << row;
  }
}

}  // namespace bsim
