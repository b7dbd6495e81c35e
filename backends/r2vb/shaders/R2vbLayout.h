// R2vbLayout.h: how the r2vb backend lays its data out in render targets,
// for its C++ passes and its shaders alike.
//
// Every r2vb pass renders one point per datum into a render target; texel
// `i` of a target W texels wide is pixel (i % W, i / W), so a row-major copy
// of the first rows to a buffer puts datum i at element i (the R2VB step).
//   cage     RGBA32F, R2VB_CAGE_WIDTH wide: texel slot * 4 + corner holds the
//            displaced corner (xyz) and its grid vertex ID (w); corners go
//            round the patch: (0,0), (1,0), (1,1), (0,1) patch-local.
//   factors  R32F, R2VB_CAGE_WIDTH wide: texel slot * 4 + edge holds the
//            edge's level, edges in Vulkan quad outer order (TerrainPatches.h),
//            so a copy is a stream of one vec4 of outer levels per slot.
//   records  R2VB_RECORD_WIDTH wide, texel r = record r (= visible slot r):
//            outer levels; (inner u, inner v, patch, 0); and one target per
//            tessellator command (TessPattern.h's five pieces).
// Here `slot` is the patch's position in the frame's visible-patch list.
#ifndef TESSERA_R2VB_LAYOUT_H
#define TESSERA_R2VB_LAYOUT_H
#include "tessera/shaders/SharedTypes.h"

/// Width of the cage and factor targets: a multiple of 4, so a slot's four
/// texels always share a row.
#define R2VB_CAGE_WIDTH 256u
/// Width of the record and command targets; records are drawn in whole rows,
/// so it is also the granularity of the record capacity.
#define R2VB_RECORD_WIDTH 32u
/// Colour attachments of the command pass: two record targets and one per
/// tessellator command.
#define R2VB_COMMAND_TARGETS 7u

/// The cage target, read by vertex texture fetch in the factor pass.
#define R2VB_BINDING_CAGE 10

TS_NAMESPACE_BEGIN

/// Push constants of every r2vb point pass.
struct R2vbTargetConstants {
    uvec4 size; // x, y: the render target's size in texels; zw unused
};
TS_CHECK_SIZE(R2vbTargetConstants, 16)

TS_NAMESPACE_END

#endif
