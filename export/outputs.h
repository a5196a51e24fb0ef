#pragma once
// The data files every export writes (formats in README): events.json, trajectory.csv, camera.csv.
#include <ostream>

namespace bsim {

struct Shot;

void write_events_json(const Shot& shot, std::ostream& out);
void write_trajectory_csv(const Shot& shot, int fps, std::ostream& out);
void write_camera_csv(const Shot& shot, int fps, std::ostream& out);

}  // namespace bsim
