#pragma once
/// @file EmulatedCrowdNearPass.h
/// An instanced crowd's near tier on the emulated backends (r2vb, streamout):
/// each near slot tessellated at its own continuous level through the
/// emulated tessellator's triangle patterns (TrianglePatternLibrary) and the
/// Listing 8 evaluation vertex shader (crowd_near_emulated.vert). Per
/// creature one multi-draw indirect over every slot's command; the backend's
/// own passes wrote the slot records, the commands (tsCrowdNearCommand) and
/// the slots' compressed cages, each with its generation's technique.

#include "common/CrowdDescriptors.h"
#include "common/CrowdPipeline.h"
#include "common/GpuCrowd.h"

#include <string>

namespace tessera::backends {

class EmulatedCrowdNearPass {
public:
    EmulatedCrowdNearPass() = default;
    /// Descriptors pushed are CrowdDescriptors::Mode::Texels'.
    EmulatedCrowdNearPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat,
                          const std::string& backendName);

    /// Inside the main pass: GPU pass crowd.near.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors);
    /// The same draws as casters into the open shadow layer of the cascade
    /// `caster` (CascadedShadowMaps::record).
    void recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                      const shader::ShadowCasterPush& caster);

private:
    CrowdPipeline mPipeline;
};

} // namespace tessera::backends
