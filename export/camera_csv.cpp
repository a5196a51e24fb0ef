// camera.csv: where the camera is and what it looks at in every frame (format in the README).
#include <string>

#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"

namespace bsim {

void write_camera_csv(const Shot& shot, int fps, std::ostream& out) {
  out << "frame,time,cam_x,cam_y,cam_z,look_x,look_y,look_z,interpolating,replay\n";
  // One row per frame of the movie (frames.h): its time is the simulation's it shows.
  const int frames = shot.movie.frame_count(fps);
  std::string row;
  for (int k = 0; k < frames; ++k) {
    const MovieFrame frame = shot.movie.frame(k, fps);
    const double t = frame.time;
    const CameraPose pose = shot.camera_at(frame).pose(t);
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
    row += pose.interpolating ? ",1" : ",0";
    row += frame.replay ? ",1\n" : ",0\n";
    out << row;
  }
}

}  // namespace bsim
