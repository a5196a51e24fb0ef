#include "write_camera.h"

#include <iostream>

#include "atomic_file.h"
#include "director.h"
#include "scene_file.h"
#include "shot.h"

namespace bsim {

int run_write_camera(const std::string& path, const Shot& shot, bool quiet) {
  // The script the shot was loaded with (--write-camera implies --camera auto), else written now.
  const std::string text =
      camera_script_text(shot.directed ? *shot.directed : direct_camera(shot.scene, shot.timeline), shot.scene.name);
  return write_text_output(path, text, quiet);
}

int write_text_output(const std::string& path, const std::string& text, bool quiet) {
  if (path == "-") {
    std::cout << text << std::flush;
    return std::cout ? 0 : 1;
  }
  std::string error;
  if (!write_file_atomically(path, text, error)) {
    std::cerr << "billiards-preview: error: " << error << "\n";
    return 1;
  }
  if (!quiet) std::cerr << "wrote " << path << "\n";
  return 0;
}

}  // namespace bsim
