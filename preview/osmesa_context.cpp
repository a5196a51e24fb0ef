#include "osmesa_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include "gl_loader.h"

namespace bsim {

namespace {

struct OsmesaApi {
  decltype(&OSMesaCreateContextAttribs) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc = nullptr;
};

// The library stays loaded for the life of the process: Mesa keeps driver state in it.
const OsmesaApi* osmesa_api(std::string& error) {
  static OsmesaApi api;
  static bool tried = false;
  if (!tried) {
    tried = true;
    void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
    if (lib) {
      api.create = reinterpret_cast<decltype(api.create)>(dlsym(lib, "OSMesaCreateContextAttribs"));
      api.make_current = reinterpret_cast<decltype(api.make_current)>(dlsym(lib, "OSMesaMakeCurrent"));
      api.destroy = reinterpret_cast<decltype(api.destroy)>(dlsym(lib, "OSMesaDestroyContext"));
      api.get_proc = reinterpret_cast<decltype(api.get_proc)>(dlsym(lib, "OSMesaGetProcAddress"));
    }
  }
  if (!api.create || !api.make_current || !api.destroy || !api.get_proc) {
    error = "cannot load libOSMesa (install libosmesa6) for headless drawing";
    return nullptr;
  }
  return &api;
}

OSMESAproc (*g_get_proc)(const char*) = nullptr;
void (*load_proc(const char* name))() { return g_get_proc(name); }

}  // namespace

OsmesaContext::~OsmesaContext() {
  std::string ignored;
  if (context_) osmesa_api(ignored)->destroy(static_cast<OSMesaContext>(context_));
}

bool OsmesaContext::open(int width, int height, std::string& error) {
  const OsmesaApi* api = osmesa_api(error);
  if (!api) return false;
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            8,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = api->create(attributes, nullptr);
  if (!context) {
    error = "OSMesa cannot create an OpenGL 3.3 core context";
    return false;
  }
  context_ = context;
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  if (!api->make_current(context, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    error = "OSMesa cannot bind a " + std::to_string(width) + "x" + std::to_string(height) + " buffer";
    return false;
  }
  g_get_proc = api->get_proc;
  const char* missing = nullptr;
  if (!load_gl_table(load_proc, &missing)) {
    error = std::string("OSMesa lacks ") + missing;
    return false;
  }
  return true;
}

const std::vector<std::uint8_t>& OsmesaContext::pixels() {
  gl_finish();
  return buffer_;
}

}  // namespace bsim
