// Issue 22 item 9: a 1 MB title cost 21 s and 420 MB of film (every glyph laid out, packed and
// drawn each frame, almost all of them beyond the frame's right edge), and a 10 MB one needed
// SIGKILL. The layout stops at the frame: a text's quads are those of the glyphs in the frame,
// the same however long the text runs on.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "view/text.h"

namespace cablefilm {
namespace {

constexpr float kWidth = 1920, kHeight = 1080;

bool InFrame(const GlyphQuad& q) {
  float x0 = q.corner[0].x, x1 = x0, y0 = q.corner[0].y, y1 = y0;
  for (const Vec2f& c : q.corner) {
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  }
  return x1 >= 0 && x0 <= kWidth && y1 >= 0 && y0 <= kHeight;
}

bool Same(const GlyphQuad& a, const GlyphQuad& b) {
  for (int i = 0; i < 4; ++i)
    if (a.corner[i].x != b.corner[i].x || a.corner[i].y != b.corner[i].y) return false;
  return a.uv0.x == b.uv0.x && a.uv0.y == b.uv0.y && a.uv1.x == b.uv1.x && a.uv1.y == b.uv1.y;
}

TEST(TextLayout, ALongTextCostsOnlyTheGlyphsInTheFrame) {
  FontAtlas font;
  const std::string mb(1000000, 'W');           // a 1 MB title
  const std::string shown = mb.substr(0, 400);  // more than a 1920 px line holds
  struct Case {
    const char* what;
    TextItem item;
  };
  std::vector<Case> cases;
  TextItem title;  // the film's title: left, on the header's baseline
  title.pos = {24, 44};
  title.size = 30;
  title.bold = true;
  cases.push_back({"left", title});
  TextItem right = title;  // a right-aligned text running off the left edge
  right.pos = {kWidth - 24, 70};
  right.halign = HAlign::kRight;
  cases.push_back({"right", right});
  TextItem up = title;  // an axis title, reading upwards off the top
  up.pos = {40, kHeight - 100};
  up.vertical = true;
  cases.push_back({"vertical", up});
  for (Case& c : cases) {
    // The glyphs in the frame of the first 400 characters, laid out whole.
    c.item.text = c.item.halign == HAlign::kRight ? mb.substr(mb.size() - 400) : shown;
    std::vector<GlyphQuad> whole;
    font.Layout(c.item, &whole);
    std::vector<GlyphQuad> visible;
    for (const GlyphQuad& q : whole)
      if (InFrame(q)) visible.push_back(q);
    ASSERT_GT(visible.size(), 20u) << c.what;
    ASSERT_LT(visible.size(), 400u) << c.what;  // the line is longer than the frame
    // The 1 MB text clipped to the frame: those glyphs, and hardly any more.
    c.item.text = mb;
    std::vector<GlyphQuad> clipped;
    font.Layout(c.item, &clipped, kWidth, kHeight);
    EXPECT_LE(clipped.size(), visible.size() + 6) << c.what;
    EXPECT_GE(clipped.size(), visible.size()) << c.what;
    if (c.item.halign == HAlign::kRight) continue;  // placed from a 1 MB width: float round-off
    std::size_t found = 0;
    for (const GlyphQuad& v : visible)
      for (const GlyphQuad& q : clipped)
        if (Same(v, q)) {
          ++found;
          break;
        }
    EXPECT_EQ(found, visible.size()) << c.what << ": a glyph in the frame was left out";
  }
}

}  // namespace
}  // namespace cablefilm
