#version 430 core
// Keeps its own #version line, which the loader moves ahead of the defines.
uniform vec4 color;
out vec4 fragColor;

void main() { fragColor = color; }
