#include "view/gl_context.h"

#include <GL/osmesa.h>

#include "core/error.h"

#if defined(__SANITIZE_ADDRESS__)
// Mesa 22's OSMesa never frees the framebuffer records OSMesaMakeCurrent allocates (about 280
// bytes per context, also when the context is released and destroyed first): not ours to fix,
// so LeakSanitizer builds are told to ignore allocations made inside libOSMesa.
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
#endif

namespace cablefilm {

GlContext::GlContext(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw Error("OpenGL: invalid framebuffer size " + std::to_string(width) + "x" +
                std::to_string(height));
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                         OSMESA_DEPTH_BITS, 0,
                         OSMESA_STENCIL_BITS, 0,
                         OSMESA_ACCUM_BITS, 0,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 3,
                         0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx)
    throw Error("OpenGL: OSMesa could not create a 3.3 core-profile context "
                "(is libosmesa6 the gallium/llvmpipe build?)");
  context_ = ctx;
  buffer_.resize(static_cast<std::size_t>(width) * height * 4);
  try {
    MakeCurrent();
  } catch (...) {
    OSMesaDestroyContext(ctx);
    context_ = nullptr;
    throw;
  }
}

GlContext::~GlContext() {
  if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void GlContext::MakeCurrent() {
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                         width_, height_))
    throw Error("OpenGL: OSMesaMakeCurrent failed for " + std::to_string(width_) + "x" +
                std::to_string(height_));
}

std::string GlContext::Describe() const {
  auto str = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_VERSION) + ", " + str(GL_RENDERER);
}

}  // namespace cablefilm
