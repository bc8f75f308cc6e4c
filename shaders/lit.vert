#version 330 core
// The surfaces of a 3D scene (tubes, solids, sheets) in world coordinates [m], seen through the
// camera's view and projection; lit per pixel in lit.frag.
layout(location = 0) in vec3 a_pos;       // [m]
layout(location = 1) in vec3 a_normal;    // unit
layout(location = 2) in vec4 a_color;     // sRGB, straight alpha
layout(location = 3) in vec2 a_material;  // grid spacing [m] (0: none), specular strength

uniform mat4 u_view_projection;

out vec3 v_world;
out vec3 v_normal;
out vec4 v_color;
flat out vec2 v_material;

void main() {
  v_world = a_pos;
  v_normal = a_normal;
  v_color = a_color;
  v_material = a_material;
  gl_Position = u_view_projection * vec4(a_pos, 1.0);
}
