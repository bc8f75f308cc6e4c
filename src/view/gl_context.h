#pragma once
// An off-screen OpenGL 3.3 core-profile context (OSMesa: software rendering, no display, no
// GPU). The only file of the program that includes GL/osmesa.h, so another context (EGL) can
// replace it without touching the rest. A context is current on the thread that created it.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cablefilm {

class GlContext {
 public:
  // Creates the context with an RGBA colour buffer of width x height and makes it current.
  // Throws Error when OSMesa cannot give a 3.3 core context.
  GlContext(int width, int height);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void MakeCurrent();  // on the calling thread
  int width() const { return width_; }
  int height() const { return height_; }
  std::string Describe() const;  // "4.5 (Core Profile) Mesa 22.3.6, llvmpipe (...)"

 private:
  void* context_ = nullptr;  // OSMesaContext
  int width_, height_;
  std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer
};

}  // namespace cablefilm
