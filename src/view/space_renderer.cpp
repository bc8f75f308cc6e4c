#include "view/space_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/error.h"
#include "view/gl_api.h"
#include "view/shader_program.h"
#include "view/space_mesh.h"

namespace cablefilm {
namespace {

constexpr int kWantedSamples = 4;

}  // namespace

struct SpaceRenderer::Impl {
  std::unique_ptr<ShaderProgram> program;
  int u_view_projection = -1, u_eye = -1, u_light = -1;
  GLuint vao = 0, vbo = 0;
  std::size_t vbo_bytes = 0;  // the buffer's size: data goes into it while it fits
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0, resolve_fbo = 0, resolve_color = 0;
  int width = 0, height = 0, samples = 0;
  SpaceMesh mesh;

  void Resize(int w, int h);
  void Upload(const std::vector<LitVertex>& opaque, const std::vector<LitVertex>& clear);
  ~Impl() {
    program.reset();
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
    glDeleteFramebuffers(1, &msaa_fbo);
    glDeleteFramebuffers(1, &resolve_fbo);
    const GLuint buffers[] = {msaa_color, msaa_depth, resolve_color};
    glDeleteRenderbuffers(3, buffers);
  }
};

SpaceRenderer::SpaceRenderer(const std::string& shader_dir) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.program = std::make_unique<ShaderProgram>(shader_dir, "lit");
  m.u_view_projection = m.program->Uniform("u_view_projection");
  m.u_eye = m.program->Uniform("u_eye");
  m.u_light = m.program->Uniform("u_light");
  glGenVertexArrays(1, &m.vao);
  glGenBuffers(1, &m.vbo);
  glBindVertexArray(m.vao);
  glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
  const GLsizei stride = sizeof(LitVertex);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LitVertex, pos)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LitVertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, reinterpret_cast<void*>(offsetof(LitVertex, color)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LitVertex, material)));
  glBindVertexArray(0);
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  m.samples = std::clamp(static_cast<int>(max_samples), 0, kWantedSamples);
  glGenFramebuffers(1, &m.msaa_fbo);
  glGenFramebuffers(1, &m.resolve_fbo);
  GLuint buffers[3];
  glGenRenderbuffers(3, buffers);
  m.msaa_color = buffers[0];
  m.msaa_depth = buffers[1];
  m.resolve_color = buffers[2];
  CheckGl("setting up the 3D renderer");
}

SpaceRenderer::~SpaceRenderer() = default;

int SpaceRenderer::samples() const { return impl_->samples; }

void SpaceRenderer::Impl::Resize(int w, int h) {
  if (w == width && h == height) return;
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
  const GLenum msaa_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color);
  const GLenum resolve_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (msaa_status != GL_FRAMEBUFFER_COMPLETE || resolve_status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("OpenGL: the 3D view's " + std::to_string(w) + "x" + std::to_string(h) +
                " framebuffer is incomplete (status 0x" + std::to_string(msaa_status) + ", 0x" +
                std::to_string(resolve_status) + ")");
  CheckGl("sizing the 3D view's framebuffer");
  width = w;
  height = h;
}

void SpaceRenderer::Impl::Upload(const std::vector<LitVertex>& opaque,
                                 const std::vector<LitVertex>& clear) {
  const std::size_t a = opaque.size() * sizeof(LitVertex), b = clear.size() * sizeof(LitVertex);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  if (a + b > vbo_bytes) {  // grown: a new store with room to spare, kept from then on
    vbo_bytes = (a + b) + (a + b) / 2;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vbo_bytes), nullptr, GL_STREAM_DRAW);
  }
  if (a) glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(a), opaque.data());
  if (b) glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(a), static_cast<GLsizeiptr>(b), clear.data());
}

void SpaceRenderer::Draw(const Scene3& scene, int frame_width, int frame_height) {
  Impl& m = *impl_;
  // The rectangle in whole pixels, inside the frame.
  const int x0 = std::clamp(static_cast<int>(std::lround(scene.corner0.x)), 0, frame_width);
  const int y0 = std::clamp(static_cast<int>(std::lround(scene.corner0.y)), 0, frame_height);
  const int x1 = std::clamp(static_cast<int>(std::lround(scene.corner1.x)), 0, frame_width);
  const int y1 = std::clamp(static_cast<int>(std::lround(scene.corner1.y)), 0, frame_height);
  const int w = x1 - x0, h = y1 - y0;
  if (w <= 0 || h <= 0) return;
  m.Resize(w, h);
  m.mesh.Build(scene);
  const std::vector<LitVertex>& opaque = m.mesh.opaque();
  const std::vector<LitVertex>& clear = m.mesh.see_through();

  glBindFramebuffer(GL_FRAMEBUFFER, m.msaa_fbo);
  glViewport(0, 0, w, h);
  glClearColor(scene.background.r, scene.background.g, scene.background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  if (!opaque.empty() || !clear.empty()) {
    m.Upload(opaque, clear);
    m.program->Use();
    glUniformMatrix4fv(m.u_view_projection, 1, GL_FALSE, scene.view_projection);
    glUniform3f(m.u_eye, scene.eye.x, scene.eye.y, scene.eye.z);
    glUniform3f(m.u_light, scene.light.x, scene.light.y, scene.light.z);
    glBindVertexArray(m.vao);
    glDisable(GL_BLEND);
    if (!opaque.empty()) glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(opaque.size()));
    if (!clear.empty()) {  // over the opaque parts, hidden by those in front, hiding nothing
      glEnable(GL_BLEND);
      glDepthMask(GL_FALSE);
      glDrawArrays(GL_TRIANGLES, static_cast<GLint>(opaque.size()),
                   static_cast<GLsizei>(clear.size()));
      glDepthMask(GL_TRUE);
    }
    glBindVertexArray(0);
  }
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  // Resolve the samples (same rectangle, as a multisampled blit must be), then copy into the
  // frame upside down: GL's rows run up, the frame's rows (GL row 0 its top) run down.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.msaa_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m.resolve_fbo);
  glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.resolve_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, w, h, x0, y1, x1, y0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, frame_width, frame_height);
  CheckGl("drawing a 3D view of " + std::to_string(opaque.size() + clear.size()) + " vertices");
}

}  // namespace cablefilm
