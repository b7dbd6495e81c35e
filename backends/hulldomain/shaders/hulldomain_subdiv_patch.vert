#version 450
// hulldomain's subdivision draw: one patch of one control point per domain,
// the control point carrying only its domain's index. The hull and domain
// stages take the index from it rather than from gl_PrimitiveID, which
// restarts at every draw of HulldomainSubdivPass's batches.
layout(location = 0) out uint outDomain;

void main() {
    outDomain = uint(gl_VertexIndex);
}
