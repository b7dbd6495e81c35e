#version 450
// r2vb's crowd point passes (classify, lists, near commands, near skin):
// writes the texel the point carries (counts, a list entry, half a command,
// a compressed cage vertex) into its RGBA32UI target.
layout(location = 0) flat in uvec4 inTexel;
layout(location = 0) out uvec4 outTexel;

void main() {
    outTexel = inTexel;
}
