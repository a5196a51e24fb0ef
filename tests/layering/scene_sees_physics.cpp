// Must not compile: see CMakeLists.txt.
#include "timeline.h"
