// Must not compile: see CMakeLists.txt.
#include "scene_renderer.h"
