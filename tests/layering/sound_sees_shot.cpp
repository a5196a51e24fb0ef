// Must not compile: see CMakeLists.txt.
#include "shot.h"
