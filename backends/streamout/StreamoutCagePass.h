#pragma once
/// @file StreamoutCagePass.h
/// "streamout.cage": transforms the control mesh once per frame. Every grid
/// vertex of the terrain's cage goes through a vertex shader that displaces it
/// from the height map, and transform feedback writes (world xyz, vertex ID)
/// into the slot's cage buffer (streamout_cage.vert). The cull and factor
/// passes load patch corners from it by grid vertex ID.

#include "StreamoutPassInputs.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutCagePass {
public:
    StreamoutCagePass() = default;
    explicit StreamoutCagePass(gpu::Device& device);

    /// Records the pass, then a barrier that makes the cage readable as a
    /// texel buffer by the vertex and geometry stages.
    void record(const StreamoutPassInputs& in);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
