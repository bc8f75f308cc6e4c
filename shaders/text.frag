#version 330 core
// FreeType's 8-bit coverage as alpha. Blending is done on sRGB values, which makes linear
// coverage look thin for light text on dark ground: u_gamma < 1 compensates.
in vec2 v_uv;
flat in vec4 v_color;

uniform sampler2D u_atlas;
uniform float u_gamma;

out vec4 frag_color;

void main() {
  float coverage = pow(texture(u_atlas, v_uv).r, u_gamma);
  float alpha = v_color.a * coverage;
  if (alpha <= 0.0) discard;
  frag_color = vec4(v_color.rgb, alpha);
}
