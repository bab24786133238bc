#version 330 core
in vec4 Frag_Color;
layout(location = 0) out vec4 Out_Color;

void main() {
  Out_Color = Frag_Color;
}
