// Must not compile: see CMakeLists.txt.
#include "soundtrack.h"
