#pragma once
/// @file FrameReport.h
/// A backend's own account of a frame, for tests of the data model and for
/// the HUD. GPU-measured figures live in the profiler, not here.

#include "tessera/shaders/CrowdLod.h"

#include <cstdint>

namespace tessera::backend {

struct FrameReport {
    uint64_t frameIndex = 0;
    uint32_t terrainPatchesDrawn = 0;
    uint32_t splatsApplied = 0;
    /// Character instances drawn and their control-cage triangles (the
    /// superprimitives before tessellation).
    uint32_t charactersDrawn = 0;
    uint64_t characterCageTriangles = 0;
    /// The characters' tessellated triangles (also in trianglesSubmitted):
    /// with characterCageTriangles, the paper's amplification.
    uint64_t characterTriangles = 0;
    /// Triangles the backend submitted (before clipping), as it computes them.
    uint64_t trianglesSubmitted = 0;
    /// Crowd instances drawn per LOD tier (near, middle, far, impostor;
    /// fading copies included) and their triangles before tessellation (the near tier's
    /// cage triangles; what tessellation made of them is in the pass's
    /// pipeline statistics), as the GPU's lists counted them: a backend
    /// reads its counters back when the frame slot comes round again, so
    /// they describe an earlier frame of the same crowd.
    uint32_t crowdInstances[TS_LOD_TIERS] = {};
    uint64_t crowdTriangles[TS_LOD_TIERS] = {};
    /// Device bytes of the crowds drawn this frame: meshes, clips, lists,
    /// commands, near slots, per-frame instances and the technique's own
    /// state and intermediate targets (also in intermediateBytes).
    uint64_t crowdBytes = 0;
    /// Subdivision-surface tessellation domains submitted (before culling;
    /// what tessellation made of them is in the passes' pipeline statistics).
    uint32_t subdivDomains = 0;
    uint32_t passes = 0;
    /// Bytes of the backend's intermediate buffers and render targets (cage,
    /// factors, records, commands, pattern library), for the backend comparison.
    uint64_t intermediateBytes = 0;
};

} // namespace tessera::backend
