// subdiv_patch.glsl: a base-surface patch (tessera::subdiv::SubdivSurface,
// PatchData.h) evaluated on the GPU with OpenSubdiv's own basis functions
// (osd_patch_basis.glsl, generated at build time by tools/osdglsl from
// Osd::GLSLPatchShaderSource), as the second paper's domain shader and the
// emulated backends' evaluation vertex shader do, so the GPU runs the code
// OpenSubdiv's viewers run rather than a re-derivation.
#ifndef SUBDIV_PATCH_GLSL
#define SUBDIV_PATCH_GLSL
#include "osd_patch_basis.glsl"

// The weights of `patchType` (PatchData.h's values: 6 regular B-spline, 16
// points; 9 Gregory basis end cap, 20 points) at the patch's own (s, t),
// with the first and second derivatives' weights per (u, v) of the patch's
// ptex face: OpenSubdiv's normalized basis scaled by the patch's size in
// its ptex face (2^depth, or 2^(depth - 1) for a patch of a non-quad face,
// whose ptex face is a quad sub-face: see PatchParam::nonQuadRoot).
// `param` is PatchParam's two packed words and the sharpness bits. Returns
// the number of points.
int tsSubdivBasis2(uint patchType, uvec3 param, vec2 st, out float wP[20], out float wDu[20], out float wDv[20],
                   out float wDuu[20], out float wDuv[20], out float wDvv[20]) {
    OsdPatchParam p = OsdPatchParamInit(int(param.x), int(param.y), uintBitsToFloat(param.z));
    int n = OsdEvaluatePatchBasisNormalized(int(patchType), p, st.x, st.y, wP, wDu, wDv, wDuu, wDuv, wDvv);
    float scale = float(1 << OsdPatchParamGetDepth(p)) * (OsdPatchParamGetNonQuadRoot(p) != 0 ? 0.5 : 1.0);
    float scale2 = scale * scale;
    for (int i = 0; i < n; ++i) {
        wDu[i] *= scale;
        wDv[i] *= scale;
        wDuu[i] *= scale2;
        wDuv[i] *= scale2;
        wDvv[i] *= scale2;
    }
    return n;
}

// The same without second derivatives (their weights are computed and
// dropped: OpenSubdiv evaluates them together).
int tsSubdivBasis(uint patchType, uvec3 param, vec2 st, out float wP[20], out float wDu[20], out float wDv[20]) {
    float wDuu[20], wDuv[20], wDvv[20];
    return tsSubdivBasis2(patchType, param, st, wP, wDu, wDv, wDuu, wDuv, wDvv);
}

// Patch-local (s, t) of ptex (u, v) (OpenSubdiv's PatchParam::Normalize).
vec2 tsSubdivPatchCoord(uvec3 param, vec2 ptexUv) {
    OsdPatchParam p = OsdPatchParamInit(int(param.x), int(param.y), uintBitsToFloat(param.z));
    float uv[2] = float[2](ptexUv.x, ptexUv.y);
    OsdPatchParamNormalize(p, uv);
    return vec2(uv[0], uv[1]);
}

#endif
