#include "common/SubdivPipelines.h"

namespace tessera::backends {

SubdivPipelines::SubdivPipelines(gpu::Device& device, gpu::GraphicsPipelineDesc desc, const std::string& base,
                                 bool wireframe) {
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
    for (int twoSided = 0; twoSided < 2; ++twoSided) {
        desc.cullMode = twoSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        mPipelines[twoSided] = FillWirePipelines(device, desc, base + (twoSided ? ".twoSided" : ".closed"), wireframe);
    }
}

} // namespace tessera::backends
