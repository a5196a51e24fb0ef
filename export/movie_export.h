#pragma once
// POV-Ray frames, the sound track, rendering and the movie.
#include <string>

#include "export_options.h"

namespace bsim {

struct Shot;
class OutputStage;

/// Writes frames/*.pov (and the shared include) and soundtrack.wav into the stage.
bool write_frames_and_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            std::string& error);

/// Renders the committed frames in `dir` with POV-Ray and assembles dir/movie.mp4 with ffmpeg.
bool render_movie(const Shot& shot, const ExportOptions& options, const std::string& dir, std::string& error);

}  // namespace bsim
