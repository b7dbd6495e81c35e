#version 450
// Shading of a displaced subdivision surface, shared by every backend: the
// displaced normal per pixel from the tile's derivatives there
// (tsSubdivShadingNormal, with or without the Weingarten term), no normal
// map; or a debug view (patches, levels, mip levels).
#extension GL_GOOGLE_include_directive : require
#define TS_SUBDIV_FRAGMENT 1
#include "common_frame.glsl"
#include "sky_atmosphere.glsl"
#include "subdiv_eval.glsl"
#include "subdiv_varyings.glsl"

layout(location = 0) out vec4 outColor;

vec3 tsHeat(float t) {
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

vec3 tsPatchColor(uint domain, vec2 ptexUv) {
    SubdivDomain d = tsSubdivLoadDomain(domain);
    uint patchIndex = tsSubdivFindPatch(d.topology.x, clamp(ptexUv, 0.0, 1.0));
    if (patchIndex == TS_SUBDIV_EMPTY) return vec3(1.0, 0.0, 1.0);
    uvec4 p = texelFetch(subdivPatches, int(patchIndex));
    float depth = float(p.w & 0xfu);
    // Regular patches in greens by depth, end caps red.
    if ((p.x & 0xffu) == TS_SUBDIV_PATCH_GREGORY_BASIS) return vec3(0.85, 0.2, 0.15);
    return mix(vec3(0.55, 0.8, 0.45), vec3(0.15, 0.4, 0.75), clamp(depth / 4.0, 0.0, 1.0));
}

void main() {
    TsSubdivVertex v = tsSubdivReadVaryings();
    vec3 n = tsSubdivShadingNormal(ioDomain, v);
    n = normalize(mat3(subdiv.normalMatrix) * n);
    if (!gl_FrontFacing) n = -n;
    vec3 albedo = subdiv.albedo.rgb;
    uint view = subdiv.modes.z;
    if (view == TS_SUBDIV_VIEW_PATCHES) albedo = tsPatchColor(ioDomain, v.ptexUv);
    if (view == TS_SUBDIV_VIEW_LEVELS) albedo = tsHeat(log2(max(v.level, 1.0)) / 6.0);
    if (view == TS_SUBDIV_VIEW_MIPS) {
        SubdivDomain d = tsSubdivLoadDomain(ioDomain);
        TileRecord r = tsSubdivTileRecord(d.topology.x);
        float resolution = tsTileResolution(r, clamp(v.ptexUv, 0.0, 1.0), tsSubdivTileDensity(d, v.level));
        albedo = tsHeat(1.0 - (float(tsTileLog2Size(r)) - resolution) / 6.0);
    }
    vec3 sun = normalize(frame.sunDirection.xyz);
    float diffuse = max(dot(n, sun), 0.0);
    if (tsFullLook()) {
        // Albedo and debug colours are display (sRGB) values: light them in
        // linear space so the debug views keep their hues after the output
        // transform.
        vec3 lit = tsSrgbToLinear(albedo) * (frame.sunColor.rgb * diffuse + tsSkyAmbient(n));
        outColor = tsOutputColor(tsApplyFog(lit, ioWorld));
        return;
    }
    float hemi = 0.5 + 0.5 * n.y;
    vec3 ambient = mix(vec3(0.20, 0.18, 0.15), vec3(0.38, 0.45, 0.55), hemi);
    vec3 color = albedo * (ambient + vec3(1.0, 0.95, 0.85) * diffuse);
    outColor = tsOutputColor(tsApplyFog(color, ioWorld));
}
