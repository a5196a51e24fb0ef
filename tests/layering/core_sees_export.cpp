// Must not compile: see CMakeLists.txt.
#include "pov_frame.h"
