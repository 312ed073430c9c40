#version 450
// The instance's colour; its alpha drives alpha-to-coverage where the pipeline enables it.
layout(location = 0) flat in vec4 rect_color;
layout(location = 0) out vec4 color;

void main() { color = rect_color; }
