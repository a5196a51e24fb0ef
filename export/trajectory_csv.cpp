// trajectory.csv: every ball's exact state at every frame time (format in README).
#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"

namespace bsim {

namespace {

/// The numbers of one row after the ball's index, in column order.
std::array<double, 13> row_values(const BallState& s) {
  const Quat& q = s.orientation;
  return {s.position.x(), s.position.y(), s.position.z(), s.velocity.x(), s.velocity.y(), s.velocity.z(), s.spin.x(),
          s.spin.y(),     s.spin.z(),     q.w(),          q.x(),          q.y(),          q.z()};
}

/// What follows the time in one ball's row, kept while the ball's state repeats (a ball at rest, or
/// in its pocket, prints the same numbers frame after frame; equal doubles print the same text).
struct BallRow {
  bool written = false;
  std::array<double, 13> values{};
  Motion motion = Motion::stationary;
  std::string text;  ///< ",ball,x,...,state\n"
};

}  // namespace

void write_trajectory_csv(const Shot& shot, int fps, std::ostream& out) {
  const Timeline& timeline = shot.timeline;
  out << "time,ball,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,state\n";
  const int frames = frame_count(timeline.duration(), fps);
  std::vector<BallRow> rows(static_cast<std::size_t>(timeline.ball_count()));
  std::string time, frame;
  for (int k = 0; k < frames; ++k) {
    const double t = frame_time(k, fps);
    time.clear();
    append_number(time, t);
    frame.clear();
    for (int i = 0; i < timeline.ball_count(); ++i) {
      const BallState s = timeline.state(i, t);
      const std::array<double, 13> values = row_values(s);
      BallRow& row = rows[static_cast<std::size_t>(i)];
      if (!row.written || values != row.values || s.motion != row.motion) {
        row.written = true;
        row.values = values;
        row.motion = s.motion;
        row.text = ',' + std::to_string(i);
        for (double v : values) {
          row.text += ',';
          append_number(row.text, v);
        }
        row.text += ',';
        row.text += to_string(s.motion);
        row.text += '\n';
      }
      frame += time;
      frame += row.text;
    }
    out << frame;
  }
}

}  // namespace bsim
