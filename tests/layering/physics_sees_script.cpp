// Must not compile: see CMakeLists.txt.
#include "camera_script.h"
