#include "dejavu.h"

#include <filesystem>

namespace bsim {

std::string find_dejavu(const char* file) {
  static const char* const kDirectories[] = {"/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/TTF",
                                             "/usr/share/fonts/dejavu", "/usr/local/share/fonts"};
  for (const char* directory : kDirectories) {
    std::filesystem::path path = std::filesystem::path(directory) / file;
    std::error_code ignored;
    if (std::filesystem::is_regular_file(path, ignored)) return path.string();
  }
  return {};
}

}  // namespace bsim
