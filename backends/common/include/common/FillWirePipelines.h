#pragma once
/// @file FillWirePipelines.h
/// The pair every visible draw keeps (terrain, characters, surfaces): its
/// graphics pipeline drawing filled, named `base`.fill, and, where the
/// device draws polygons as lines (fillModeNonSolid), the same pipeline as
/// lines for the wireframe view, `base`.wireframe.

#include "tessera/gpu/Pipeline.h"

#include <string>

namespace tessera::backends {

class FillWirePipelines {
public:
    FillWirePipelines() = default;
    /// Makes both from `desc` (its name and polygon mode are set here);
    /// the wireframe one only when `wireframe` (the device can).
    FillWirePipelines(gpu::Device& device, gpu::GraphicsPipelineDesc desc, const std::string& base, bool wireframe);

    /// The wireframe pipeline when `wireframe` and there is one, else the filled one.
    const gpu::Pipeline& get(bool wireframe) const { return wireframe && mWire.valid() ? mWire : mFill; }

private:
    gpu::Pipeline mFill;
    gpu::Pipeline mWire;
};

} // namespace tessera::backends
