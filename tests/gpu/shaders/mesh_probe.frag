#version 460
// The tile's index in red and green (tiles < 65536), blue full.
layout(location = 0) flat in uint tile;
layout(location = 0) out vec4 color;

void main() {
    color = vec4(float(tile & 255u), float(tile >> 8u), 255.0, 255.0) / 255.0;
}
