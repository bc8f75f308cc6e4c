#include "view/text.h"

#include <fontconfig/fontconfig.h>
#include <unistd.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include "core/error.h"

namespace cablefilm {

std::vector<std::string> FindFontFiles(const std::vector<std::string>& patterns) {
  // One configuration for all the patterns: loading it (its XML files and the font caches) is
  // most of the cost, about 3 ms each time.
  FcConfig* config = FcInitLoadConfigAndFonts();
  if (!config) throw Error("fontconfig: cannot load its configuration");
  std::vector<std::string> files;
  for (const std::string& pattern : patterns) {
    FcPattern* pat = FcNameParse(reinterpret_cast<const FcChar8*>(pattern.c_str()));
    std::string file;
    if (pat) {
      FcConfigSubstitute(config, pat, FcMatchPattern);
      FcDefaultSubstitute(pat);
      FcResult result = FcResultNoMatch;
      FcPattern* match = FcFontMatch(config, pat, &result);
      FcChar8* path = nullptr;
      if (match && FcPatternGetString(match, FC_FILE, 0, &path) == FcResultMatch && path)
        file = reinterpret_cast<const char*>(path);
      if (match) FcPatternDestroy(match);
      FcPatternDestroy(pat);
    }
    if (file.empty()) {
      FcConfigDestroy(config);
      throw Error("fontconfig found no font for '" + pattern +
                  "' (install fonts-dejavu-core or give a font path)");
    }
    files.push_back(file);
  }
  FcConfigDestroy(config);
  return files;
}

std::string FindFontFile(const std::string& pattern) { return FindFontFiles({pattern})[0]; }

namespace {

// The default faces, Book and Bold: where fonts-dejavu-core (a dependency of the package)
// puts them, when both are there, else as fontconfig matches "DejaVu Sans". Loading
// fontconfig's configuration costs 3 to 4 ms of CPU, a twentieth of a short `run --no-film`,
// for the two files fontconfig itself answers on Debian.
std::vector<std::string> DefaultFontFiles() {
  const std::vector<std::string> debian = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                           "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"};
  if (::access(debian[0].c_str(), R_OK) == 0 && ::access(debian[1].c_str(), R_OK) == 0)
    return debian;
  return FindFontFiles({"DejaVu Sans:style=Book", "DejaVu Sans:weight=bold"});
}

}  // namespace

std::u32string DecodeUtf8(const std::string& s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    char32_t cp = len == 1 ? c : len == 2 ? (c & 0x1f) : len == 3 ? (c & 0x0f) : (c & 0x07);
    bool ok = len > 0 && i + len <= s.size();
    for (int k = 1; ok && k < len; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xc0) != 0x80) ok = false;
      cp = (cp << 6) | (d & 0x3f);
    }
    out.push_back(ok ? cp : U'\uFFFD');
    i += ok ? len : 1;
  }
  return out;
}

struct FontAtlas::Face {
  FT_Face face = nullptr;
  int pixel_size = 0;
  float cap_height_em = 0.73f;  // from the OS/2 table when present
  float descender_em = 0.24f;
};

namespace {
std::string FtError(FT_Error e) {
  const char* s = FT_Error_String(e);
  return s ? s : "FreeType error " + std::to_string(e);
}
}  // namespace

FontAtlas::FontAtlas(const std::string& font_path, int atlas_size)
    : size_(atlas_size),
      pixels_(static_cast<std::uint8_t*>(
          std::calloc(static_cast<std::size_t>(atlas_size) * atlas_size, 1))) {
  if (!pixels_) throw std::bad_alloc();
  if (font_path.empty()) {
    const std::vector<std::string> files = DefaultFontFiles();
    paths_[0] = files[0];
    paths_[1] = files[1];
  } else {
    paths_[0] = paths_[1] = font_path;
  }
  FT_Library lib = nullptr;
  if (FT_Error e = FT_Init_FreeType(&lib)) throw Error("FreeType: cannot initialise: " + FtError(e));
  library_ = lib;
  for (int i = 0; i < 2; ++i) {
    faces_[i] = std::make_unique<Face>();
    if (FT_Error e = FT_New_Face(lib, paths_[i].c_str(), 0, &faces_[i]->face)) {
      for (int j = 0; j <= i; ++j)
        if (faces_[j]->face) FT_Done_Face(faces_[j]->face);
      FT_Done_FreeType(lib);
      library_ = nullptr;
      throw Error("FreeType: cannot open font " + paths_[i] + ": " + FtError(e));
    }
    FT_Face f = faces_[i]->face;
    if (const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(f, FT_SFNT_OS2)))
      if (os2->sCapHeight > 0 && f->units_per_EM > 0)
        faces_[i]->cap_height_em = static_cast<float>(os2->sCapHeight) / f->units_per_EM;
    if (f->units_per_EM > 0)
      faces_[i]->descender_em = -static_cast<float>(f->descender) / f->units_per_EM;
  }
}

FontAtlas::~FontAtlas() {
  for (auto& f : faces_)
    if (f && f->face) FT_Done_Face(f->face);
  if (library_) FT_Done_FreeType(static_cast<FT_Library>(library_));
}

FontAtlas::Face& FontAtlas::SizedFace(int pixel_size, bool bold) {
  Face& f = *faces_[bold ? 1 : 0];
  if (f.pixel_size != pixel_size) {
    if (FT_Error e = FT_Set_Pixel_Sizes(f.face, 0, static_cast<FT_UInt>(pixel_size)))
      throw Error("FreeType: cannot set size " + std::to_string(pixel_size) + " px: " + FtError(e));
    f.pixel_size = pixel_size;
  }
  return f;
}

const FontAtlas::Glyph& FontAtlas::GetGlyph(char32_t code, int pixel_size, bool bold) {
  const std::uint64_t key = (static_cast<std::uint64_t>(bold) << 63) |
                            (static_cast<std::uint64_t>(pixel_size) << 32) | code;
  auto it = glyphs_.find(key);
  if (it != glyphs_.end()) return it->second;
  Face& face = SizedFace(pixel_size, bold);
  FT_Face f = face.face;
  FT_UInt index = FT_Get_Char_Index(f, code);
  if (FT_Error e = FT_Load_Glyph(f, index, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT))
    throw Error("FreeType: cannot render U+" + std::to_string(static_cast<unsigned>(code)) + ": " +
                FtError(e));
  const FT_Bitmap& bm = f->glyph->bitmap;
  Glyph g;
  g.w = static_cast<int>(bm.width);
  g.h = static_cast<int>(bm.rows);
  g.left = f->glyph->bitmap_left;
  g.top = f->glyph->bitmap_top;
  g.advance = static_cast<float>(f->glyph->advance.x) / 64.0f;
  if (g.w > 0 && g.h > 0) {
    // Shelf packing with a 1-texel gap so bilinear sampling never bleeds between glyphs.
    if (shelf_x_ + g.w + 1 > size_) {
      shelf_x_ = 1;
      shelf_y_ += shelf_h_ + 1;
      shelf_h_ = 0;
    }
    if (shelf_y_ + g.h + 1 > size_ || g.w + 2 > size_)
      throw Error("text: glyph atlas of " + std::to_string(size_) + " px is full");
    g.x = shelf_x_;
    g.y = shelf_y_;
    shelf_x_ += g.w + 1;
    shelf_h_ = std::max(shelf_h_, g.h);
    for (int r = 0; r < g.h; ++r)
      std::memcpy(&pixels_[static_cast<std::size_t>(g.y + r) * size_ + g.x],
                  bm.buffer + static_cast<std::ptrdiff_t>(r) * bm.pitch, static_cast<std::size_t>(g.w));
    dirty_ = true;
  }
  return glyphs_.emplace(key, g).first->second;
}

float FontAtlas::MeasureWidth(const std::string& text, float size, bool bold) {
  const int px = std::max(1, static_cast<int>(std::lround(size)));
  float w = 0;
  for (char32_t c : DecodeUtf8(text)) w += GetGlyph(c, px, bold).advance;
  return w;
}

void FontAtlas::Layout(const TextItem& item, std::vector<GlyphQuad>* quads, float clip_width,
                       float clip_height) {
  const int px = std::max(1, static_cast<int>(std::lround(item.size)));
  const Face& face = SizedFace(px, item.bold);
  const std::u32string text = DecodeUtf8(item.text);
  float width = 0;
  if (item.halign != HAlign::kLeft)
    for (char32_t c : text) width += GetGlyph(c, px, item.bold).advance;
  // (u, v): along the text from its anchor, and down from it, before any rotation.
  float u0 = 0;
  if (item.halign == HAlign::kCenter) u0 = -width / 2;
  if (item.halign == HAlign::kRight) u0 = -width;
  float baseline = 0;
  const float cap = face.cap_height_em * px, desc = face.descender_em * px;
  switch (item.valign) {
    case VAlign::kTop: baseline = cap; break;
    case VAlign::kMiddle: baseline = cap / 2; break;
    case VAlign::kBaseline: baseline = 0; break;
    case VAlign::kBottom: baseline = -desc; break;
  }
  // Snap the pen to whole pixels across the text so the glyph bitmaps stay crisp.
  const float ax = std::round(item.pos.x), ay = std::round(item.pos.y);
  const float inv = 1.0f / size_;
  float pen = std::round(u0);
  baseline = std::round(baseline);
  // Along the text, the frame ends at `beyond` (u grows rightwards, or upwards when vertical);
  // a glyph that starts past it, and every one after it, is outside. A margin of a glyph's
  // size either side keeps a glyph that reaches into the frame.
  const float margin = 2.0f * px;
  const float beyond = item.vertical ? ay + margin : clip_width - ax + margin;
  const float before = item.vertical ? ay - clip_height - margin : -ax - margin;
  for (char32_t c : text) {
    if (pen > beyond) break;  // advances are never negative: the rest is further on
    const Glyph& g = GetGlyph(c, px, item.bold);
    if (pen < before) {  // not in the frame yet: only the pen moves
      pen += g.advance;
      continue;
    }
    if (g.w > 0 && g.h > 0) {
      const float gu0 = std::round(pen) + g.left, gu1 = gu0 + g.w;
      const float gv0 = baseline - g.top, gv1 = gv0 + g.h;
      GlyphQuad q;
      auto place = [&](float u, float v) {
        return item.vertical ? Vec2f{ax + v, ay - u} : Vec2f{ax + u, ay + v};
      };
      q.corner[0] = place(gu0, gv0);
      q.corner[1] = place(gu1, gv0);
      q.corner[2] = place(gu1, gv1);
      q.corner[3] = place(gu0, gv1);
      q.uv0 = {g.x * inv, g.y * inv};
      q.uv1 = {(g.x + g.w) * inv, (g.y + g.h) * inv};
      quads->push_back(q);
    }
    pen += g.advance;
  }
}

}  // namespace cablefilm
