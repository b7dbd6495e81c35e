#version 450
// streamout.crowd.cull, pixel stage: a survivor's point covers its id's
// texel of this frame's state target; the texel takes its next state, which
// the next frame's cull pass loads.
layout(location = 0) flat in uvec2 inSurvivor; // (instance, next state)
layout(location = 0) out uint outState;

void main() {
    outState = inSurvivor.y;
}
