#pragma once
// Text with FreeType: fonts found through fontconfig (DejaVu Sans by default) or given by path,
// glyphs rasterised on demand (anti-aliased, 8-bit coverage) into one CPU-side atlas that the
// renderer uploads as a texture, and the layout of a TextItem into positioned glyph quads.
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "view/frame.h"

namespace cablefilm {

// The font file fontconfig picks for a pattern such as "DejaVu Sans:style=Book". Throws Error.
std::string FindFontFile(const std::string& pattern);
// The files of several patterns, fontconfig's configuration loaded once. Throws Error.
std::vector<std::string> FindFontFiles(const std::vector<std::string>& patterns);
std::u32string DecodeUtf8(const std::string& text);  // invalid bytes become U+FFFD

struct GlyphQuad {
  Vec2f corner[4];  // screen positions [px]: top left, top right, bottom right, bottom left
  Vec2f uv0, uv1;   // atlas texture coordinates of the bitmap's top left and bottom right
};

class FontAtlas {
 public:
  // `font_path` empty: DejaVu Sans (Book and Bold), Debian's files or through fontconfig; else
  // that file for both.
  explicit FontAtlas(const std::string& font_path = "", int atlas_size = 1024);
  ~FontAtlas();
  FontAtlas(const FontAtlas&) = delete;
  FontAtlas& operator=(const FontAtlas&) = delete;

  // Appends the quads of `item`, rasterising any glyph not yet in the atlas. Only the glyphs
  // within the frame (0 to clip_width, 0 to clip_height) are laid out: the rest of a long
  // text costs no glyph, quad or vertex (the text's width is still measured to align it).
  void Layout(const TextItem& item, std::vector<GlyphQuad>* quads,
              float clip_width = std::numeric_limits<float>::infinity(),
              float clip_height = std::numeric_limits<float>::infinity());
  // Advance width of the text at a pixel size [px].
  float MeasureWidth(const std::string& text, float size, bool bold = false);

  int atlas_size() const { return size_; }
  const std::uint8_t* pixels() const { return pixels_.get(); }  // size x size, R8
  bool dirty() const { return dirty_; }
  void ClearDirty() { dirty_ = false; }
  const std::string& regular_path() const { return paths_[0]; }

 private:
  struct Glyph {
    int x = 0, y = 0, w = 0, h = 0;  // place in the atlas
    int left = 0, top = 0;           // bitmap offset from the pen, FreeType's bitmap_left/top
    float advance = 0;               // [px]
  };
  struct Face;
  const Glyph& GetGlyph(char32_t code, int pixel_size, bool bold);
  Face& SizedFace(int pixel_size, bool bold);

  struct Free {
    void operator()(std::uint8_t* p) const { std::free(p); }
  };
  int size_;
  // calloc's zeros: a block this large is mapped afresh, its pages zero until written, so only
  // the rows the glyphs take are ever touched (max_tension.png uses a few dozen of the 1024: a
  // vector's zeros cost 256 page faults, about 5 ms on the test machine).
  std::unique_ptr<std::uint8_t[], Free> pixels_;
  bool dirty_ = true;
  int shelf_x_ = 1, shelf_y_ = 1, shelf_h_ = 0;
  std::string paths_[2];
  void* library_ = nullptr;  // FT_Library
  std::unique_ptr<Face> faces_[2];
  std::unordered_map<std::uint64_t, Glyph> glyphs_;
};

}  // namespace cablefilm
