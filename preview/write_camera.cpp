#include "write_camera.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "director.h"
#include "shot.h"

namespace bsim {

int run_write_camera(const std::string& path, const Shot& shot) {
  // The script the shot was loaded with (--write-camera implies --camera auto), else written now.
  const std::string text =
      camera_script_text(shot.directed ? *shot.directed : direct_camera(shot.scene, shot.timeline), shot.scene.name);
  if (path == "-") {
    std::cout << text << std::flush;
    return std::cout ? 0 : 1;
  }
  const std::filesystem::path target(path);
  const std::filesystem::path temporary = target.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
      std::cerr << "billiards-preview: error: cannot write " << path << ": " << std::strerror(errno) << "\n";
      std::remove(temporary.c_str());
      return 1;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    std::cerr << "billiards-preview: error: cannot write " << path << ": " << ec.message() << "\n";
    std::remove(temporary.c_str());
    return 1;
  }
  std::cerr << "wrote " << path << "\n";
  return 0;
}

}  // namespace bsim
