// PLACEHOLDER until the movie lands.
#include "movie_export.h"
namespace bsim {
bool write_frames_and_sound(const Shot&, const ExportOptions&, const OutputStage&, std::string& error) {
  error = "frames are not built yet";
  return false;
}
bool render_movie(const Shot&, const ExportOptions&, const std::string&, std::string& error) {
  error = "rendering is not built yet";
  return false;
}
}  // namespace bsim
