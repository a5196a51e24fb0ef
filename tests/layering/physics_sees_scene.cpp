// Must compile: physics reads the scene.
#include "scene.h"
#include "timeline.h"

int bsim_layering_control() { return static_cast<int>(sizeof(bsim::Scene) + sizeof(bsim::Timeline)); }
