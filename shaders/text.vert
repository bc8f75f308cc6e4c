#version 330 core
// Glyph quads in pixel coordinates (origin top left, y down), sampled from the glyph atlas.
layout(location = 0) in vec2 a_pos;    // [px]
layout(location = 1) in vec2 a_uv;     // atlas coordinates
layout(location = 2) in vec4 a_color;  // sRGB, straight alpha

uniform vec2 u_viewport;

out vec2 v_uv;
flat out vec4 v_color;

void main() {
  v_uv = a_uv;
  v_color = a_color;
  gl_Position = vec4(a_pos / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
