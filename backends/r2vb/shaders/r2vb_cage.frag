#version 450
// Pass r2vb.cage: writes the corner computed by the vertex shader.
layout(location = 0) flat in vec4 inCorner;
layout(location = 0) out vec4 outCorner;

void main() {
    outCorner = inCorner;
}
