// PLACEHOLDER until the data files land.
#include "outputs.h"
namespace bsim {
void write_events_json(const Shot&, std::ostream&) {}
void write_trajectory_csv(const Shot&, int, std::ostream&) {}
void write_camera_csv(const Shot&, int, std::ostream&) {}
}  // namespace bsim
