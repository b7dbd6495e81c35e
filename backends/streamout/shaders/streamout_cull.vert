#version 450
// streamout.cull, vertex stage: one point per patch the CPU found visible,
// its index from the per-vertex stream; the geometry stage does the work.
layout(location = 0) in uint inPatch;
layout(location = 0) out uint vPatch;

void main() {
    vPatch = inPatch;
}
