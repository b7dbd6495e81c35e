#include "common/FillWirePipelines.h"

namespace tessera::backends {

FillWirePipelines::FillWirePipelines(gpu::Device& device, gpu::GraphicsPipelineDesc desc, const std::string& base,
                                     bool wireframe) {
    desc.name = base + ".fill";
    desc.polygonMode = VK_POLYGON_MODE_FILL;
    mFill = gpu::Pipeline(device, desc);
    if (!wireframe) return;
    desc.name = base + ".wireframe";
    desc.polygonMode = VK_POLYGON_MODE_LINE;
    mWire = gpu::Pipeline(device, desc);
}

} // namespace tessera::backends
