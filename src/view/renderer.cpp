#include "view/renderer.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/error.h"
#include "view/gl_api.h"
#include "view/gl_context.h"
#include "view/shader_program.h"
#include "view/space_renderer.h"
#include "view/text.h"

namespace cablefilm {
namespace {

struct ShapeVertex {
  float pos[2];
  float geom[4];
  float param[2];
  std::uint8_t color[4];
};

struct TextVertex {
  float pos[2];
  float uv[2];
  std::uint8_t color[4];
};

void PackColor(const Rgba& c, std::uint8_t out[4]) {
  auto q = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::fmin(1.0f, std::fmax(0.0f, v)) * 255));
  };
  out[0] = q(c.r);
  out[1] = q(c.g);
  out[2] = q(c.b);
  out[3] = q(c.a);
}

// Appends the vertices of one shape: a quad around it (one pixel of margin for the
// anti-aliasing ramp) as two triangles, or the triangle itself.
void EmitShape(const Shape& s, std::vector<ShapeVertex>* out) {
  ShapeVertex v{};
  v.geom[0] = s.a.x;
  v.geom[1] = s.a.y;
  v.geom[2] = s.b.x;
  v.geom[3] = s.b.y;
  v.param[0] = s.size;
  v.param[1] = static_cast<float>(static_cast<int>(s.kind));
  PackColor(s.color, v.color);
  if (s.kind == ShapeKind::kTriangle) {
    for (const Vec2f& p : {s.a, s.b, s.c}) {
      v.pos[0] = p.x;
      v.pos[1] = p.y;
      out->push_back(v);
    }
    return;
  }
  Vec2f c[4];
  switch (s.kind) {
    case ShapeKind::kSegment: {
      float dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
      const float len = std::sqrt(dx * dx + dy * dy);
      if (len > 1e-6f) {
        dx /= len;
        dy /= len;
      } else {
        dx = 1;
        dy = 0;
      }
      const float e = std::fmax(s.size, 1.0f) * 0.5f + 1.0f;
      const float ux = dx * e, uy = dy * e, nx = -dy * e, ny = dx * e;
      c[0] = {s.a.x - ux + nx, s.a.y - uy + ny};
      c[1] = {s.b.x + ux + nx, s.b.y + uy + ny};
      c[2] = {s.b.x + ux - nx, s.b.y + uy - ny};
      c[3] = {s.a.x - ux - nx, s.a.y - uy - ny};
      break;
    }
    case ShapeKind::kRect: {
      const float x0 = std::fmin(s.a.x, s.b.x) - 1, x1 = std::fmax(s.a.x, s.b.x) + 1;
      const float y0 = std::fmin(s.a.y, s.b.y) - 1, y1 = std::fmax(s.a.y, s.b.y) + 1;
      c[0] = {x0, y0};
      c[1] = {x1, y0};
      c[2] = {x1, y1};
      c[3] = {x0, y1};
      break;
    }
    default: {  // disc, diamond: centre a, radius size
      const float r = s.size + 1;
      c[0] = {s.a.x - r, s.a.y - r};
      c[1] = {s.a.x + r, s.a.y - r};
      c[2] = {s.a.x + r, s.a.y + r};
      c[3] = {s.a.x - r, s.a.y + r};
      break;
    }
  }
  for (int i : {0, 1, 2, 0, 2, 3}) {
    v.pos[0] = c[i].x;
    v.pos[1] = c[i].y;
    out->push_back(v);
  }
}

}  // namespace

struct Renderer::Impl {
  RenderOptions options;
  std::unique_ptr<GlContext> context;
  std::unique_ptr<ShaderProgram> shape_program, text_program;
  std::unique_ptr<FontAtlas> font;
  GLuint shape_vao = 0, shape_vbo = 0, text_vao = 0, text_vbo = 0, atlas = 0;
  int shape_viewport = -1, text_viewport = -1, text_atlas = -1, text_gamma = -1;
  std::vector<ShapeVertex> shape_vertices;
  std::vector<std::size_t> scene_starts;  // the shape vertex each 3D scene is drawn before
  std::vector<TextVertex> text_vertices;
  std::vector<GlyphQuad> quads;
  std::unique_ptr<SpaceRenderer> space;

  void DrawShapes(std::size_t first, std::size_t end) const {
    if (end <= first) return;
    shape_program->Use();
    glBindVertexArray(shape_vao);
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(end - first));
  }

  ~Impl() {
    if (!context) return;
    context->MakeCurrent();
    space.reset();
    shape_program.reset();
    text_program.reset();
    glDeleteBuffers(1, &shape_vbo);
    glDeleteBuffers(1, &text_vbo);
    glDeleteVertexArrays(1, &shape_vao);
    glDeleteVertexArrays(1, &text_vao);
    glDeleteTextures(1, &atlas);
  }
};

Renderer::Renderer(const RenderOptions& options) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.options = options;
  m.context = std::make_unique<GlContext>(options.width, options.height);
  const std::string dir = ResolveShaderDir(options.shader_dir);
  m.shape_program = std::make_unique<ShaderProgram>(dir, "shape");
  m.text_program = std::make_unique<ShaderProgram>(dir, "text");
  m.shape_viewport = m.shape_program->Uniform("u_viewport");
  m.text_viewport = m.text_program->Uniform("u_viewport");
  m.text_atlas = m.text_program->Uniform("u_atlas");
  m.text_gamma = m.text_program->Uniform("u_gamma");
  m.font = std::make_unique<FontAtlas>(options.font_path);
  m.space = std::make_unique<SpaceRenderer>(dir);

  glGenVertexArrays(1, &m.shape_vao);
  glGenBuffers(1, &m.shape_vbo);
  glBindVertexArray(m.shape_vao);
  glBindBuffer(GL_ARRAY_BUFFER, m.shape_vbo);
  const GLsizei ss = sizeof(ShapeVertex);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, ss, reinterpret_cast<void*>(offsetof(ShapeVertex, pos)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, ss, reinterpret_cast<void*>(offsetof(ShapeVertex, geom)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, ss, reinterpret_cast<void*>(offsetof(ShapeVertex, param)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, ss, reinterpret_cast<void*>(offsetof(ShapeVertex, color)));

  glGenVertexArrays(1, &m.text_vao);
  glGenBuffers(1, &m.text_vbo);
  glBindVertexArray(m.text_vao);
  glBindBuffer(GL_ARRAY_BUFFER, m.text_vbo);
  const GLsizei ts = sizeof(TextVertex);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, ts, reinterpret_cast<void*>(offsetof(TextVertex, pos)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, ts, reinterpret_cast<void*>(offsetof(TextVertex, uv)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, ts, reinterpret_cast<void*>(offsetof(TextVertex, color)));
  glBindVertexArray(0);

  glGenTextures(1, &m.atlas);
  glBindTexture(GL_TEXTURE_2D, m.atlas);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const int n = m.font->atlas_size();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, n, n, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
  // Glyph quads sit on whole pixels, so nearest sampling reproduces FreeType's bitmaps exactly.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  // Straight alpha over an opaque frame; the frame's alpha stays 1.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glViewport(0, 0, options.width, options.height);
  CheckGl("setting up the renderer");
}

Renderer::~Renderer() = default;

int Renderer::width() const { return impl_->options.width; }
int Renderer::height() const { return impl_->options.height; }
std::string Renderer::Describe() const { return impl_->context->Describe(); }

Image Renderer::Draw(const Frame& frame) {
  Image image;
  Draw(frame, &image);
  return image;
}

void Renderer::Draw(const Frame& frame, Image* out) {
  Impl& m = *impl_;
  const int w = m.options.width, h = m.options.height;
  if (frame.width != w || frame.height != h)
    throw Error("renderer: frame is " + std::to_string(frame.width) + "x" +
                std::to_string(frame.height) + ", renderer is " + std::to_string(w) + "x" +
                std::to_string(h));
  m.context->MakeCurrent();
  glClearColor(frame.background.r, frame.background.g, frame.background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  // The shapes in one buffer, drawn in runs between the 3D scenes placed among them.
  m.shape_vertices.clear();
  m.scene_starts.clear();
  for (std::size_t i = 0; i < frame.shapes.size(); ++i) {
    while (m.scene_starts.size() < frame.scenes.size() &&
           frame.scenes[m.scene_starts.size()].after_shapes <= i)
      m.scene_starts.push_back(m.shape_vertices.size());
    EmitShape(frame.shapes[i], &m.shape_vertices);
  }
  while (m.scene_starts.size() < frame.scenes.size())
    m.scene_starts.push_back(m.shape_vertices.size());
  if (!m.shape_vertices.empty()) {
    m.shape_program->Use();
    glUniform2f(m.shape_viewport, static_cast<float>(w), static_cast<float>(h));
    glBindBuffer(GL_ARRAY_BUFFER, m.shape_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.shape_vertices.size() * sizeof(ShapeVertex)),
                 m.shape_vertices.data(), GL_STREAM_DRAW);
  }
  std::size_t drawn = 0;
  for (std::size_t k = 0; k < frame.scenes.size(); ++k) {
    m.DrawShapes(drawn, m.scene_starts[k]);
    drawn = m.scene_starts[k];
    m.space->Draw(frame.scenes[k], w, h);
  }
  m.DrawShapes(drawn, m.shape_vertices.size());
  CheckGl("drawing " + std::to_string(frame.shapes.size()) + " shapes and " +
          std::to_string(frame.scenes.size()) + " 3D scenes");

  m.text_vertices.clear();
  for (const TextItem& t : frame.texts) {
    m.quads.clear();
    m.font->Layout(t, &m.quads, static_cast<float>(w), static_cast<float>(h));
    TextVertex v{};
    PackColor(t.color, v.color);
    for (const GlyphQuad& q : m.quads) {
      const Vec2f uv[4] = {q.uv0, {q.uv1.x, q.uv0.y}, q.uv1, {q.uv0.x, q.uv1.y}};
      for (int i : {0, 1, 2, 0, 2, 3}) {
        v.pos[0] = q.corner[i].x;
        v.pos[1] = q.corner[i].y;
        v.uv[0] = uv[i].x;
        v.uv[1] = uv[i].y;
        m.text_vertices.push_back(v);
      }
    }
  }
  if (!m.text_vertices.empty()) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m.atlas);
    if (m.font->dirty()) {
      const int n = m.font->atlas_size();
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, n, GL_RED, GL_UNSIGNED_BYTE, m.font->pixels());
      m.font->ClearDirty();
    }
    m.text_program->Use();
    glUniform2f(m.text_viewport, static_cast<float>(w), static_cast<float>(h));
    glUniform1i(m.text_atlas, 0);
    // Light text on a dark ground needs its coverage lifted (see text.frag).
    const Rgba& bg = frame.background;
    const float luma = 0.2126f * bg.r + 0.7152f * bg.g + 0.0722f * bg.b;
    glUniform1f(m.text_gamma, luma < 0.5f ? 0.8f : 1.0f);
    glBindVertexArray(m.text_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m.text_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.text_vertices.size() * sizeof(TextVertex)),
                 m.text_vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(m.text_vertices.size()));
    CheckGl("drawing " + std::to_string(frame.texts.size()) + " text items");
  }
  glBindVertexArray(0);

  // GL's row 0 is the frame's top row (see shape.vert): read back as is.
  if (out->width != w || out->height != h || out->rgba.size() != static_cast<std::size_t>(w) * h * 4)
    *out = Image(w, h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out->rgba.data());
  CheckGl("reading back the frame");
}

}  // namespace cablefilm
