#pragma once
/// @file TessellationCapture.h
/// Test support: runs the device's fixed-function tessellator on one patch
/// with given levels and captures, through transform feedback, the
/// tessellation coordinate of every vertex of every emitted triangle, so the
/// emulated tessellator can be compared with the real one.

#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::test {

enum class CaptureDomain { Triangle, Quad };
enum class CaptureSpacing { Equal, FractionalOdd, FractionalEven };

struct TessellationCaptureResult {
    /// Three tessellation coordinates (gl_TessCoord) per emitted triangle.
    std::vector<glm::vec3> vertices;
    /// Primitives the transform-feedback query counted as written.
    uint64_t primitivesWritten = 0;
    /// Tessellation-evaluation invocations (pipeline statistics).
    uint64_t evaluationInvocations = 0;
};

class TessellationCapture {
public:
    explicit TessellationCapture(gpu::Device& device);
    ~TessellationCapture();
    TessellationCapture(const TessellationCapture&) = delete;
    TessellationCapture& operator=(const TessellationCapture&) = delete;

    /// Tessellates one patch; outer[3] and inner[1] are ignored by triangles.
    Result<TessellationCaptureResult> run(CaptureDomain domain, CaptureSpacing spacing, const std::array<float, 4>& outer,
                                          const std::array<float, 2>& inner);

private:
    gpu::Device& mDevice;
    gpu::PipelineLayout mLayout;
    std::array<gpu::Pipeline, 6> mPipelines; ///< [domain * 3 + spacing]
    gpu::Buffer mCapture;
    gpu::Buffer mCounter;
    VkQueryPool mStreamQueries = VK_NULL_HANDLE; ///< primitives written to transform feedback
    VkQueryPool mStatsQueries = VK_NULL_HANDLE;  ///< tessellation-evaluation invocations
};

} // namespace tessera::test
