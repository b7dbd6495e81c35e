#pragma once
/// @file StreamoutFactorPass.h
/// "streamout.factors": per-patch tessellation levels and tessellator
/// commands from stream output. A draw-auto (vkCmdDrawIndirectByteCountEXT)
/// over the cull pass's survivors runs one vertex-shader invocation per
/// surviving patch (streamout_factors.vert); transform feedback writes its
/// record (outer levels; inner levels and patch index) and its five
/// tessellator commands, in the layout EmulatedTerrainBackend draws.

#include "StreamoutPassInputs.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class StreamoutFactorPass {
public:
    /// Fails, in words, when the device's transform feedback cannot write the
    /// pass's three streams (or cannot draw-auto).
    static Status checkDevice(const gpu::Device& device);

    StreamoutFactorPass() = default;
    explicit StreamoutFactorPass(gpu::Device& device);

    /// Clears the commands, records the pass, then a barrier that makes
    /// records and commands ready for the emulated draw's indirect and
    /// vertex-shader reads. `keyTable` holds shader::TsEmuKeyTable.
    /// `visiblePatches`: the draw's visible patches, a bound on the survivors.
    void record(const StreamoutPassInputs& in, const gpu::Buffer& keyTable, uint32_t visiblePatches);

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
