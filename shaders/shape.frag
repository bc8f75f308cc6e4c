#version 330 core
// Anti-aliasing without MSAA: each shape's coverage of a pixel is estimated from the signed
// distance of the pixel centre to its edge, clamp(0.5 - distance, 0, 1), a one-pixel ramp.
in vec2 v_px;
flat in vec4 v_geom;
flat in vec2 v_param;
flat in vec4 v_color;

out vec4 frag_color;

const float kSegment = 0.0, kDisc = 1.0, kRect = 2.0, kDiamond = 3.0;

float SegmentDistance(vec2 p, vec2 a, vec2 b) {
  vec2 ab = b - a;
  float len2 = dot(ab, ab);
  float h = len2 > 0.0 ? clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length(p - a - h * ab);
}

void main() {
  float kind = v_param.y;
  float size = v_param.x;
  float alpha = v_color.a;
  float coverage = 1.0;
  if (kind < kSegment + 0.5) {
    // Lines thinner than a pixel are drawn one pixel wide with their width as opacity.
    float half_width = max(size, 1.0) * 0.5;
    alpha *= min(size, 1.0);
    coverage = clamp(half_width + 0.5 - SegmentDistance(v_px, v_geom.xy, v_geom.zw), 0.0, 1.0);
  } else if (kind < kDisc + 0.5) {
    coverage = clamp(size + 0.5 - length(v_px - v_geom.xy), 0.0, 1.0);
  } else if (kind < kRect + 0.5) {
    vec2 centre = 0.5 * (v_geom.xy + v_geom.zw);
    vec2 half_size = 0.5 * abs(v_geom.zw - v_geom.xy);
    vec2 d = abs(v_px - centre) - half_size;
    coverage = clamp(0.5 - max(d.x, d.y), 0.0, 1.0);
  } else if (kind < kDiamond + 0.5) {
    vec2 d = abs(v_px - v_geom.xy);
    coverage = clamp(0.5 - (d.x + d.y - size) * 0.70710678, 0.0, 1.0);
  }
  alpha *= coverage;
  if (alpha <= 0.0) discard;
  frag_color = vec4(v_color.rgb, alpha);
}
