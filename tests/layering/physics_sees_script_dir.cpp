// Must not compile: see CMakeLists.txt.
#include "script/camera_script.h"
