#version 450
// hulldomain's subdivision draw: one patch of one control point per domain;
// the hull and domain stages read everything by gl_PrimitiveID.
void main() {
}
