// trajectory.csv: every ball's exact state at every frame time (format in README).
#include <ostream>
#include <string>

#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"

namespace bsim {

void write_trajectory_csv(const Shot& shot, int fps, std::ostream& out) {
  const Timeline& timeline = shot.timeline;
  out << "time,ball,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,state\n";
  const int frames = frame_count(timeline.duration(), fps);
  std::string row;
  for (int k = 0; k < frames; ++k) {
    const double t = frame_time(k, fps);
    const std::string time = format_number(t);
    for (int i = 0; i < timeline.ball_count(); ++i) {
      const BallState s = timeline.state(i, t);
      const Quat& q = s.orientation;
      row = time + ',' + std::to_string(i);
      for (double v : {s.position.x(), s.position.y(), s.position.z(), s.velocity.x(), s.velocity.y(), s.velocity.z(),
                       s.spin.x(), s.spin.y(), s.spin.z(), q.w(), q.x(), q.y(), q.z()})
        row += ',' + format_number(v);
      row += ',';
      row += to_string(s.motion);
      row += '\n';
      out << row;
    }
  }
}

}  // namespace bsim
