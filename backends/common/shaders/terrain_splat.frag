#version 450
// Splats one crater into the height map: each fragment is one height sample
// (the viewport is the whole map), read from the scratch copy of the region
// and rewritten with the same formula the CPU copy uses (CraterProfile.h).
// Both images are seen through R16_UINT views, so the old sample is read and
// the new one written as exact integers, with no UNORM conversion whose
// rounding could differ from the CPU's.
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CraterProfile.h"

layout(set = 0, binding = 0) uniform usampler2D oldHeights;
layout(push_constant) uniform SplatBlock {
    CraterSplatParams splat;
};
layout(location = 0) out uint outHeight;

void main() {
    ivec2 sample_ = ivec2(gl_FragCoord.xy);
    // Same operations and order as terrain::applyCrater; precise keeps the
    // compiler from fusing them differently from the CPU.
    precise float dx = float(sample_.x) * splat.centerRadius.w - splat.centerRadius.x;
    precise float dz = float(sample_.y) * splat.centerRadius.w - splat.centerRadius.y;
    precise float distanceSq = dx * dx + dz * dz;
    // Outside the radius nothing is written at all, so those samples stay
    // bit-identical whatever the UNORM round trip would do.
    if (distanceSq >= splat.centerRadius.z * splat.centerRadius.z) discard;
    int old = int(texelFetch(oldHeights, sample_, 0).r);
    outHeight = uint(clamp(old + tsCraterDelta(distanceSq, splat), 0, 65535));
}
