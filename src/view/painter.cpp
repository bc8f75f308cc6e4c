#include "view/painter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cablefilm {

void Painter::Triangle(Vec2f a, Vec2f b, Vec2f c, Rgba color) {
  Shape s;
  s.kind = ShapeKind::kTriangle;
  s.a = a;
  s.b = b;
  s.c = c;
  s.color = color;
  f_.shapes.push_back(s);
}

void Painter::Polyline(const std::vector<Vec2f>& p, float width, Rgba c) {
  for (std::size_t i = 1; i < p.size(); ++i) Line(p[i - 1], p[i], width, c);
  if (p.size() == 1) Disc(p[0], width / 2, c);
}

void Painter::Dashed(const std::vector<Vec2f>& p, float width, Rgba c, float dash, float gap) {
  float phase = 0;  // distance into the current dash+gap period [px]
  const float period = dash + gap;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const float dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y;
    const float len = std::sqrt(dx * dx + dy * dy);
    float s = 0;
    while (s < len) {
      const bool on = phase < dash;
      const float run = std::min(len - s, on ? dash - phase : period - phase);
      if (on && run > 0.01f)
        Line({p[i - 1].x + dx * s / len, p[i - 1].y + dy * s / len},
             {p[i - 1].x + dx * (s + run) / len, p[i - 1].y + dy * (s + run) / len}, width, c);
      s += run;
      phase = std::fmod(phase + run, period);
    }
  }
}

void Painter::Text(std::string text, Vec2f pos, float size, Rgba c, HAlign h, VAlign v,
                   bool vertical, bool bold) {
  TextItem t;
  t.text = std::move(text);
  t.pos = pos;
  t.size = std::max(kMinFontSize, size);
  t.color = c;
  t.halign = h;
  t.valign = v;
  t.vertical = vertical;
  t.bold = bold;
  f_.texts.push_back(std::move(t));
}

void Painter::Add(ShapeKind kind, Vec2f a, Vec2f b, float size, Rgba c) {
  Shape s;
  s.kind = kind;
  s.a = a;
  s.b = b;
  s.size = size;
  s.color = c;
  f_.shapes.push_back(s);
}

float EstimateTextWidth(const std::string& s, float size, bool bold) {
  int chars = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++chars;  // count UTF-8 lead bytes: one per character
  return (bold ? 0.65f : 0.6f) * std::max(kMinFontSize, size) * chars;
}

std::string FormatValue(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

}  // namespace cablefilm
