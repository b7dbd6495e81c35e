#version 450
// Pass r2vb.factors: writes the edge level computed by the vertex shader.
layout(location = 0) flat in float inLevel;
layout(location = 0) out float outLevel;

void main() {
    outLevel = inLevel;
}
