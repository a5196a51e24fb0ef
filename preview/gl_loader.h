#pragma once
// Filling the GL function table, without the GL headers (so OSMesa's and GLFW's headers can sit beside it).

namespace bsim {

/// Where entry points come from: OSMesaGetProcAddress or glfwGetProcAddress.
using GlProcLoader = void (*(*)(const char* name))();

/// Fills the table from `loader` for the context that is current now. Returns false and names the
/// first missing entry point in `missing` when the context lacks one.
bool load_gl_table(GlProcLoader loader, const char** missing);

/// glFinish through the table.
void gl_finish();

}  // namespace bsim
