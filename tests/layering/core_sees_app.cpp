// Must not compile: see CMakeLists.txt.
#include "command_line.h"
