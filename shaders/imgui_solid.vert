#version 330 core
// ImGui's vertex layout and projection (as its OpenGL3 backend's shader), for its solid-colour triangles:
// engine/render/imgui_solid_fills.hpp.
layout(location = 0) in vec2 Position;
layout(location = 2) in vec4 Color;

uniform mat4 ProjMtx;

out vec4 Frag_Color;

void main() {
  Frag_Color = Color;
  gl_Position = ProjMtx * vec4(Position.xy, 0, 1);
}
