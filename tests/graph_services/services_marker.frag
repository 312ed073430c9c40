#version 450
layout(location = 0) out vec4 color;

void main() { color = vec4(0.25, 0.5, 1.0, 1.0); }  // kMarkerColor in tests/test_graph_services.cpp
