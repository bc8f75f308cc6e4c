#include "view/renderer.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/error.h"
#include "view/damage.h"
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

  // Redrawing only what changed (RenderOptions::redraw_changes): this frame's items (the
  // shapes, then the texts) and the first vertex of each, the last frame's, and the passes.
  std::vector<DrawnItem> items, previous_items;
  std::vector<std::size_t> item_first;
  bool previous_valid = false;  // the framebuffer holds previous_items drawn, and only them
  double redrawn = 1;           // the share of the frame the last Draw drew
  bool read_whole_or_changes = false;  // the last read back finished
  Rgba background;
  std::unique_ptr<Damage> damage;
  std::vector<ImageRect> rects;
  std::vector<ShapeVertex> pass_shapes;
  std::vector<TextVertex> pass_texts;
  struct Pass {
    ImageRect rect;
    std::size_t shapes_begin, shapes_end, texts_begin, texts_end;
  };
  std::vector<Pass> passes;

  // The item drawn by vertices[first..]: their hash and their pixel bounds.
  template <typename Vertex>
  void AddItem(const std::vector<Vertex>& vertices, std::size_t first) {
    DrawnItem item;
    item.hash = HashBytes(vertices.data() + first, (vertices.size() - first) * sizeof(Vertex));
    float x0 = vertices[first].pos[0], x1 = x0, y0 = vertices[first].pos[1], y1 = y0;
    for (std::size_t i = first + 1; i < vertices.size(); ++i) {
      x0 = std::fmin(x0, vertices[i].pos[0]);
      x1 = std::fmax(x1, vertices[i].pos[0]);
      y0 = std::fmin(y0, vertices[i].pos[1]);
      y1 = std::fmax(y1, vertices[i].pos[1]);
    }
    // A pixel is drawn when its centre is inside a triangle: within the vertices' bounds, less
    // a pixel's margin for safety. (Clamped first: a shape far off the frame stays an int.)
    auto px = [](float v) { return std::fmax(-1e6f, std::fmin(1e6f, v)); };
    item.x0 = static_cast<int>(std::floor(px(x0))) - 1;
    item.y0 = static_cast<int>(std::floor(px(y0))) - 1;
    item.x1 = static_cast<int>(std::ceil(px(x1))) + 1;
    item.y1 = static_cast<int>(std::ceil(px(y1))) + 1;
    if (!(x0 == x0 && x1 == x1 && y0 == y0 && y1 == y1)) {  // NaN: anywhere
      item.x0 = item.y0 = -1000000;
      item.x1 = item.y1 = 1000000;
    }
    items.push_back(item);
    item_first.push_back(first);
  }

  void DrawShapes(std::size_t first, std::size_t end) const {
    if (end <= first) return;
    shape_program->Use();
    glBindVertexArray(shape_vao);
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(end - first));
  }

  void DrawTexts(std::size_t first, std::size_t end) const {
    if (end <= first) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, atlas);
    text_program->Use();
    glBindVertexArray(text_vao);
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(end - first));
  }

  // Each of `rects` cleared and drawn again, clipped to it, from the items that reach into it
  // (in their order): the same pixels as drawing the whole frame, where it changed.
  void DrawChanges(std::size_t shape_items) {
    pass_shapes.clear();
    pass_texts.clear();
    passes.clear();
    for (const ImageRect& r : rects) {
      Pass p{r, pass_shapes.size(), 0, pass_texts.size(), 0};
      for (std::size_t i = 0; i < items.size(); ++i) {
        const DrawnItem& it = items[i];
        if (it.x1 <= r.x0 || it.x0 >= r.x1 || it.y1 <= r.y0 || it.y0 >= r.y1) continue;
        if (i < shape_items) {
          const std::size_t end = i + 1 < shape_items ? item_first[i + 1] : shape_vertices.size();
          pass_shapes.insert(pass_shapes.end(), shape_vertices.begin() + item_first[i],
                             shape_vertices.begin() + end);
        } else {
          const std::size_t end = i + 1 < items.size() ? item_first[i + 1] : text_vertices.size();
          pass_texts.insert(pass_texts.end(), text_vertices.begin() + item_first[i],
                            text_vertices.begin() + end);
        }
      }
      p.shapes_end = pass_shapes.size();
      p.texts_end = pass_texts.size();
      passes.push_back(p);
    }
    glBindBuffer(GL_ARRAY_BUFFER, shape_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(pass_shapes.size() * sizeof(ShapeVertex)),
                 pass_shapes.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, text_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(pass_texts.size() * sizeof(TextVertex)),
                 pass_texts.data(), GL_STREAM_DRAW);
    glEnable(GL_SCISSOR_TEST);
    for (const Pass& p : passes) {
      // GL's row 0 is the frame's top row (see shape.vert): the rectangle as it is.
      glScissor(p.rect.x0, p.rect.y0, p.rect.x1 - p.rect.x0, p.rect.y1 - p.rect.y0);
      glClear(GL_COLOR_BUFFER_BIT);
      DrawShapes(p.shapes_begin, p.shapes_end);
      DrawTexts(p.texts_begin, p.texts_end);
    }
    glDisable(GL_SCISSOR_TEST);
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
  // Tiles of 32 px: bounding boxes of the changes drawn as fewer, larger passes cost more here
  // (llvmpipe pays for pixels more than for passes: 1080p live frames, bench_live.py).
  m.damage = std::make_unique<Damage>(options.width, options.height, 32);

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

double Renderer::redrawn() const { return impl_->redrawn; }
const std::vector<ImageRect>& Renderer::redrawn_rects() const { return impl_->rects; }
int Renderer::width() const { return impl_->options.width; }
int Renderer::height() const { return impl_->options.height; }
std::string Renderer::Describe() const { return impl_->context->Describe(); }

void Renderer::DrawOnto(const Frame& frame, Image* picture) {
  Render(frame);
  ReadBack(picture, true);
}

// GL's row 0 is the frame's top row (see shape.vert): read back as is, all of it or only what
// the last Draw drew again.
void Renderer::ReadBack(Image* out, bool changes_only) {
  Impl& m = *impl_;
  const int w = m.options.width, h = m.options.height;
  if (out->width != w || out->height != h || out->rgba.size() != static_cast<std::size_t>(w) * h * 4) {
    *out = Image(w, h);
    changes_only = false;
  }
  const bool last_read = m.read_whole_or_changes;
  m.read_whole_or_changes = false;  // until this read is done (a failed one leaves it unknown)
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (changes_only && last_read && m.redrawn < 1) {
    glPixelStorei(GL_PACK_ROW_LENGTH, w);
    for (const ImageRect& r : m.rects)
      glReadPixels(r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0, GL_RGBA, GL_UNSIGNED_BYTE,
                   out->row(r.y0) + 4 * static_cast<std::size_t>(r.x0));
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  } else {
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out->rgba.data());
  }
  CheckGl("reading back the frame");
  m.read_whole_or_changes = true;
}

Image Renderer::Draw(const Frame& frame) {
  Image image;
  Draw(frame, &image);
  return image;
}

void Renderer::Draw(const Frame& frame, Image* out) {
  Render(frame);
  ReadBack(out, false);
}

void Renderer::Render(const Frame& frame) {
  Impl& m = *impl_;
  const int w = m.options.width, h = m.options.height;
  if (frame.width != w || frame.height != h)
    throw Error("renderer: frame is " + std::to_string(frame.width) + "x" +
                std::to_string(frame.height) + ", renderer is " + std::to_string(w) + "x" +
                std::to_string(h));
  m.context->MakeCurrent();

  // The shapes in one buffer, drawn in runs between the 3D scenes placed among them.
  m.shape_vertices.clear();
  m.scene_starts.clear();
  m.items.clear();
  m.item_first.clear();
  for (std::size_t i = 0; i < frame.shapes.size(); ++i) {
    while (m.scene_starts.size() < frame.scenes.size() &&
           frame.scenes[m.scene_starts.size()].after_shapes <= i)
      m.scene_starts.push_back(m.shape_vertices.size());
    const std::size_t first = m.shape_vertices.size();
    EmitShape(frame.shapes[i], &m.shape_vertices);
    if (m.options.redraw_changes) m.AddItem(m.shape_vertices, first);
  }
  while (m.scene_starts.size() < frame.scenes.size())
    m.scene_starts.push_back(m.shape_vertices.size());
  const std::size_t shape_items = m.items.size();

  m.text_vertices.clear();
  for (const TextItem& t : frame.texts) {
    const std::size_t first = m.text_vertices.size();
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
    if (m.options.redraw_changes && m.text_vertices.size() > first)
      m.AddItem(m.text_vertices, first);
  }
  const bool font_changed = m.font->dirty();
  if (font_changed) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m.atlas);
    const int n = m.font->atlas_size();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, n, GL_RED, GL_UNSIGNED_BYTE, m.font->pixels());
    m.font->ClearDirty();
  }
  m.shape_program->Use();
  glUniform2f(m.shape_viewport, static_cast<float>(w), static_cast<float>(h));
  m.text_program->Use();
  glUniform2f(m.text_viewport, static_cast<float>(w), static_cast<float>(h));
  glUniform1i(m.text_atlas, 0);
  // Light text on a dark ground needs its coverage lifted (see text.frag).
  const Rgba& bg = frame.background;
  const float luma = 0.2126f * bg.r + 0.7152f * bg.g + 0.0722f * bg.b;
  glUniform1f(m.text_gamma, luma < 0.5f ? 0.8f : 1.0f);
  glClearColor(bg.r, bg.g, bg.b, 1.0f);

  // Only what changed since the last frame, when the framebuffer still holds it drawn from
  // items alone (no 3D scene, the same ground, the glyphs where they were) and the changes are
  // not most of the frame (then one pass over everything costs less).
  const bool was_valid = m.previous_valid;
  m.previous_valid = false;  // until this frame is drawn (a failed draw leaves it unknown)
  const bool same_ground = bg.r == m.background.r && bg.g == m.background.g &&
                           bg.b == m.background.b && bg.a == m.background.a;
  bool partial = m.options.redraw_changes && was_valid && frame.scenes.empty() &&
                 same_ground && !font_changed &&
                 m.damage->Compare(m.previous_items, m.items, &m.rects);
  m.redrawn = 1;
  if (partial) {
    long area = 0;
    for (const ImageRect& r : m.rects) area += static_cast<long>(r.x1 - r.x0) * (r.y1 - r.y0);
    m.redrawn = static_cast<double>(area) / (static_cast<double>(w) * h);
    partial = m.redrawn < 0.6;
    if (!partial) m.redrawn = 1;
  }
  if (partial) {
    m.DrawChanges(shape_items);
  } else {
    glClear(GL_COLOR_BUFFER_BIT);
    if (!m.shape_vertices.empty()) {
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
    if (!m.text_vertices.empty()) {
      glBindBuffer(GL_ARRAY_BUFFER, m.text_vbo);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.text_vertices.size() * sizeof(TextVertex)),
                   m.text_vertices.data(), GL_STREAM_DRAW);
      m.DrawTexts(0, m.text_vertices.size());
    }
  }
  CheckGl("drawing " + std::to_string(frame.shapes.size()) + " shapes, " +
          std::to_string(frame.texts.size()) + " text items and " +
          std::to_string(frame.scenes.size()) + " 3D scenes");
  glBindVertexArray(0);
  m.background = bg;
  m.previous_valid = frame.scenes.empty();
  std::swap(m.previous_items, m.items);
}

}  // namespace cablefilm
