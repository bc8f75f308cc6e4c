#include "view/theme.h"

namespace cablefilm {

Rgba Hex(std::uint32_t rgb, float a) {
  return {((rgb >> 16) & 0xff) / 255.0f, ((rgb >> 8) & 0xff) / 255.0f, (rgb & 0xff) / 255.0f, a};
}

Rgba Mix(Rgba a, Rgba b, float t) {
  return {a.r * t + b.r * (1 - t), a.g * t + b.g * (1 - t), a.b * t + b.b * (1 - t), 1};
}

Rgba LineColor(const Theme& th, std::size_t line) {
  return th.line_colors[line % Theme::kLineColors];
}

float NestedWidth(std::size_t i, std::size_t n) {
  if (n < 2) return 2.4f;
  return 1.8f + 2.4f * static_cast<float>(n - 1 - i) / static_cast<float>(n - 1);
}

Theme Theme::Dark() {
  Theme t;
  t.background = Hex(0x0e1217);
  t.panel = Hex(0x161b22);
  t.grid = Hex(0x242b35);
  t.axis = Hex(0x5d6876);
  t.text = Hex(0xe8ecf1);
  t.text_dim = Hex(0x9ba6b5);
  t.current = Hex(0xf3f5f8);
  t.equilibrium = Hex(0x8792a2);
  t.envelope = Hex(0x3d8bd9, 0.38f);
  t.accent = Hex(0xff9f43);
  t.halo = Hex(0x9aa4b2);
  t.marker_fill = Hex(0x161b22);
  t.marker_edge = Hex(0xe8ecf1);
  t.overlay = Hex(0xf783ac);
  t.overlay_rim = Hex(0xd0d7e1);
  t.event = Hex(0x3bc9db);
  t.water = Hex(0x5aa9e6);   // sea blue: apart from the map's colours and the bed's olive
  t.seabed = Hex(0x8f9d5e);  // olive mud: apart from the orange of the end's path
  // Bright on the dark panel, told apart by hue (Open Color's 4-5 shades).
  const std::uint32_t lines[] = {0x4dabf7, 0xff922b, 0x69db7c, 0xf783ac,
                                 0xb197fc, 0xffd43b, 0x3bc9db, 0xe8ecf1};
  for (int i = 0; i < kLineColors; ++i) t.line_colors[i] = Hex(lines[i]);
  return t;
}

Theme Theme::Light() {
  Theme t;
  t.background = Hex(0xf4f6f8);
  t.panel = Hex(0xffffff);
  t.grid = Hex(0xe4e8ed);
  t.axis = Hex(0x6b7684);
  t.text = Hex(0x1b2129);
  t.text_dim = Hex(0x56616f);
  t.current = Hex(0x1b2129);
  t.equilibrium = Hex(0x8a94a3);
  t.envelope = Hex(0x3d8bd9, 0.3f);
  t.accent = Hex(0xd9480f);
  t.halo = Hex(0x1b2129);
  t.marker_fill = Hex(0xffffff);
  t.marker_edge = Hex(0x1b2129);
  t.overlay = Hex(0xc2255c);
  t.overlay_rim = Hex(0x56616f);
  t.event = Hex(0x1098ad);
  t.water = Hex(0x2f7fc1);
  t.seabed = Hex(0x6b7a34);
  const std::uint32_t lines[] = {0x1c7ed6, 0xe8590c, 0x2f9e44, 0xc2255c,
                                 0x7048e8, 0xe67700, 0x1098ad, 0x343a40};
  for (int i = 0; i < kLineColors; ++i) t.line_colors[i] = Hex(lines[i]);
  return t;
}

}  // namespace cablefilm
