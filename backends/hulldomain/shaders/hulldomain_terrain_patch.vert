#version 450
// One control point per patch: just the patch index (per instance). The
// control stage reads its factors and the evaluation stage computes every
// position from the index and the tessellation coordinate.
layout(location = 0) in uint inPatch;
layout(location = 0) out uint vPatch;

void main() {
    vPatch = inPatch;
}
