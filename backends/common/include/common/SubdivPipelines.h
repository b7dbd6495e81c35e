#pragma once
/// @file SubdivPipelines.h
/// A subdivision surface draw's pipelines, shared by every technique: closed
/// surfaces cull back faces, open ones draw both sides, each filled and (where
/// the device can) as a wireframe. Domains are counter-clockwise seen from
/// outside (ptex u, v follow the face's winding) and every technique emits
/// their triangles in the hardware tessellator's `ccw` order, which
/// Camera::projection's Y flip makes clockwise on screen.

#include "common/FillWirePipelines.h"
#include "common/GpuSubdiv.h"

#include <string>

namespace tessera::backends {

class SubdivPipelines {
public:
    SubdivPipelines() = default;
    /// Makes the four from `desc` (its stages, layout, inputs and formats;
    /// face and culling are set here), named "`base`.<closed|twoSided>.<fill|wireframe>".
    SubdivPipelines(gpu::Device& device, gpu::GraphicsPipelineDesc desc, const std::string& base, bool wireframe);

    /// The pipeline that draws `surface`.
    const gpu::Pipeline& get(const GpuSubdiv& surface, bool wireframe) const {
        return mPipelines[surface.closed() ? 0 : 1].get(wireframe);
    }

private:
    FillWirePipelines mPipelines[2]; ///< [two-sided]
};

} // namespace tessera::backends
