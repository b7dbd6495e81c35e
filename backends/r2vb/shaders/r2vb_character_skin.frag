#version 450
// Writes the compressed vertex the point carries into its texel.
layout(location = 0) flat in uvec4 inPacked;
layout(location = 0) out uvec4 outPacked;

void main() {
    outPacked = inPacked;
}
