#include "gl_api.h"

namespace bsim {

GlTable gl_table;

bool load_gl_table(GlProcLoader loader, const char** missing) {
  GlTable table;
  // Every entry is required: a context without one of them cannot draw the preview.
#define BSIM_GL_LOAD(type, name)                                  \
  table.name = reinterpret_cast<type>(loader("gl" #name));        \
  if (!table.name) {                                              \
    if (missing) *missing = "gl" #name;                           \
    return false;                                                 \
  }
  BSIM_GL_FUNCTIONS(BSIM_GL_LOAD)
#undef BSIM_GL_LOAD
  gl_table = table;
  return true;
}

void gl_finish() { glFinish(); }

}  // namespace bsim
