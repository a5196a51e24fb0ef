#pragma once
// The DejaVu fonts (Debian's fonts-dejavu-core, a dependency of the package): where they are installed.
#include <string>

namespace bsim {

/// Path of a DejaVu font file such as "DejaVuSans.ttf", or empty when it is not installed.
std::string find_dejavu(const char* file);

}  // namespace bsim
