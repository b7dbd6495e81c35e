#version 450
// Pass crowd.args (r2vb): writes a list's extraction draw and its count.
layout(location = 0) flat in uvec4 inDraw;
layout(location = 1) flat in uint inCount;
layout(location = 0) out uvec4 outDraw;
layout(location = 1) out uint outCount;

void main() {
    outDraw = inDraw;
    outCount = inCount;
}
