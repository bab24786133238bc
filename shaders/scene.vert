#version 330 core
// Scene vertices arrive in framebuffer pixels (top-left origin): the renderer tessellates on the CPU with the
// camera already applied, so the shader only maps pixels to clip space.
layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec4 a_color;

uniform vec2 u_framebuffer_size;

out vec4 v_color;

void main() {
  vec2 ndc = vec2(a_pixel.x / u_framebuffer_size.x * 2.0 - 1.0, 1.0 - a_pixel.y / u_framebuffer_size.y * 2.0);
  gl_Position = vec4(ndc, 0.0, 1.0);
  v_color = a_color;
}
