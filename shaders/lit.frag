#version 330 core
// One key light (u_light, towards it) over an ambient floor, Blinn-Phong: a surface facing the
// light full on shows its colour as given, one turned away keeps a third of it, so a tube reads
// round whatever its colour. Both faces are lit alike (a sheet is seen from above and below).
// A sheet with a grid draws lines along x and z every v_material.x metres, one pixel wide and
// anti-aliased from the screen-space rate of its coordinates (fwidth), fading out where the
// cells shrink to a few pixels rather than shimmering.
in vec3 v_world;
in vec3 v_normal;
in vec4 v_color;
flat in vec2 v_material;

uniform vec3 u_eye;    // [m]
uniform vec3 u_light;  // unit

out vec4 frag_color;

const float kAmbient = 0.34;

void main() {
  vec3 n = normalize(v_normal);
  vec3 view = normalize(u_eye - v_world);
  if (dot(n, view) < 0.0) n = -n;
  vec3 base = v_color.rgb;
  if (v_material.x > 0.0) {
    vec2 g = v_world.xz / v_material.x;
    vec2 rate = max(fwidth(g), vec2(1e-6));
    vec2 d = abs(fract(g - 0.5) - 0.5) / rate;  // to the nearest line [px]
    float line = 1.0 - clamp(min(d.x, d.y) - 0.25, 0.0, 1.0);
    float fade = clamp(1.6 - 6.0 * max(rate.x, rate.y), 0.0, 1.0);
    base = mix(base, min(base * 1.7 + 0.07, vec3(1.0)), line * fade);
  }
  float diffuse = max(dot(n, u_light), 0.0);
  vec3 h = normalize(u_light + view);
  float spec = v_material.y * pow(max(dot(n, h), 0.0), 48.0);
  vec3 rgb = base * (kAmbient + (1.0 - kAmbient) * diffuse) + vec3(spec);
  frag_color = vec4(min(rgb, vec3(1.0)), min(1.0, v_color.a + spec));
}
