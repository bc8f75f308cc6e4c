#version 330 core
// Shapes of a frame (segments, discs, rectangles, diamonds, fills) as quads or triangles in
// pixel coordinates (origin top left, y down). The frame is drawn upside down in GL terms so
// that GL's row 0 is the image's top row and the read-back needs no flip.
layout(location = 0) in vec2 a_pos;     // vertex [px]
layout(location = 1) in vec4 a_geom;    // shape points a.xy, b.xy [px]
layout(location = 2) in vec2 a_param;   // size (line width or radius) [px], kind
layout(location = 3) in vec4 a_color;   // sRGB, straight alpha

uniform vec2 u_viewport;  // frame size [px]

out vec2 v_px;
flat out vec4 v_geom;
flat out vec2 v_param;
flat out vec4 v_color;

void main() {
  v_px = a_pos;
  v_geom = a_geom;
  v_param = a_param;
  v_color = a_color;
  gl_Position = vec4(a_pos / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
