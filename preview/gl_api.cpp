#include "gl_api.h"

namespace bsim {

GlTable gl_table;

bool load_gl_table(GlProcLoader loader, const char** missing) {
  GlTable table;
  // Every entry is required: a context without one of them cannot draw the preview.
#define BSIM_GL_LOAD(type, name)                           \
  table.name = reinterpret_cast<type>(loader("gl" #name)); \
  if (!table.name) {                                       \
    if (missing) *missing = "gl" #name;                    \
    return false;                                          \
  }
  BSIM_GL_FUNCTIONS(BSIM_GL_LOAD)
#undef BSIM_GL_LOAD
  gl_table = table;
  return true;
}

void gl_finish() { glFinish(); }

}  // namespace bsim

// The GL drivers loaded at run time (Mesa's OSMesa and libGL, LLVM behind them) keep allocations for
// the life of the process and never free them; LeakSanitizer builds would otherwise fail on them.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n"
         "leak:libGLX_mesa.so\n"
         "leak:libGL.so\n"
         "leak:libglapi.so\n"
         "leak:libgallium\n"
         "leak:swrast_dri.so\n"
         "leak:libLLVM\n"
         "leak:libX11.so\n"
         "leak:libxcb.so\n"
         "leak:libglfw.so\n";
}

extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
