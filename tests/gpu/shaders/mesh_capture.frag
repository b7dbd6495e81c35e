#version 460
// The capture pipelines' fragment stage: the mesh stages' buffers hold the
// result; the 1x1 target only gives their primitives somewhere to go.
layout(location = 0) out vec4 color;

void main() {
    color = vec4(1.0);
}
