#pragma once
// One POV-Ray file per frame: the camera, every ball on the table or dropping into a pocket (its
// orientation as a matrix), and the cue stick while it is in the scene. The models live in the
// shared include (pov_table.h).
#include <ostream>
#include <string>

namespace bsim {

struct Shot;

/// "frame_00012": the frame's file name without extension.
std::string frame_name(int frame);

/// Writes frame `frame` of the shot, which shows t = frame / fps.
void write_pov_frame(const Shot& shot, int frame, int fps, std::ostream& out);

}  // namespace bsim
