#pragma once
/// @file StreamoutCullPass.h
/// "streamout.cull": geometry-shader culling. One point per patch the CPU
/// found visible; the geometry shader loads the patch's corners from the cage
/// buffer, tests its displaced bounds against the frustum and streams the
/// survivors' indices out (streamout_cull.geom). The transform-feedback
/// counter then holds the survivors' byte count, which the factor pass draws
/// with draw-auto, so the CPU never learns how many survived.

#include "StreamoutPassInputs.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <cstdint>
#include <span>

namespace tessera::backends {

class StreamoutCullPass {
public:
    StreamoutCullPass() = default;
    explicit StreamoutCullPass(gpu::Device& device);

    /// Records the pass over `visiblePatches`, then a barrier that makes the
    /// survivors readable as a vertex stream and the counter as indirect data.
    void record(const StreamoutPassInputs& in, std::span<const uint32_t> visiblePatches);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
