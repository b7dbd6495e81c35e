#include "common/CascadedShadowMaps.h"

#include "common/CommandHelpers.h"
#include "tessera/gpu/Device.h"
#include "tessera/scene/ShadowCascadeFit.h"
#include "tessera/scene/ShadowCascadeUniforms.h"

#include <algorithm>
#include <iterator>

namespace tessera::backends {
namespace {

// The receivers: the terrain's and characters' fragment shaders, and the
// compute terrain resolve.
constexpr VkPipelineStageFlags2 kReaders =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

} // namespace

CascadedShadowMaps::CascadedShadowMaps(gpu::Device& device, const std::string& backendName,
                                       const scene::ShadowCascadeFit::Settings& settings)
    : mDevice(&device), mSettings(settings) {
    mMap = gpu::ShadowMapArray(device, settings.resolution, settings.cascadeCount, backendName + ".shadowCascades");
}

void CascadedShadowMaps::beginFrame(gpu::FrameContext& frame, std::span<const scene::ShadowCascade> cascades,
                                    const glm::vec3& towardsSun) {
    // The host fits the cascades with the device's settings, whose
    // resolution and count the layers have; more cascades than layers is the
    // host's error, fewer leaves the last layers unread.
    mCascades = cascades.first(std::min<size_t>(cascades.size(), mMap.layers()));
    mWritten = false;
    for (size_t i = 0; i < mCascades.size(); ++i) mPushes[i] = scene::buildShadowCasterPush(mCascades, i, towardsSun);
    mUniformInfo =
        frame.pushUniform(scene::buildShadowCascadeUniforms(mCascades, mMap.size(), mSettings.pcfTaps)).descriptor();
    mMapInfo = mMap.descriptor();
    mWrites = {bufferWrite(TS_BINDING_SHADOW_CASCADES, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &mUniformInfo),
               imageWrite(TS_BINDING_SHADOW_MAP, &mMapInfo)};
}

void CascadedShadowMaps::record(gpu::FrameContext& frame, const char* passName, const DrawCasters& draw) {
    if (!active()) return;
    using Contents = gpu::ShadowMapArray::Contents;
    const Contents contents = mWritten ? Contents::Keep : Contents::Clear;
    VkCommandBuffer cmd = frame.cmd();
    gpu::PassScope pass(frame, passName);
    mMap.beginWriting(cmd, kReaders, contents);
    static const char* const kLabels[] = {"shadows.cascade0", "shadows.cascade1", "shadows.cascade2",
                                          "shadows.cascade3"};
    static_assert(std::size(kLabels) == scene::ShadowCascadeFit::kMaxCascades);
    for (uint32_t layer = 0; layer < mCascades.size(); ++layer) {
        mDevice->beginLabel(cmd, kLabels[layer]);
        mMap.beginLayer(cmd, layer, contents);
        if (draw) draw(layer, mPushes[layer]);
        mMap.endLayer(cmd);
        mDevice->endLabel(cmd);
    }
    mMap.endWriting(cmd, kReaders);
    mWritten = true;
}

void CascadedShadowMaps::finishFrame(gpu::FrameContext& frame) {
    if (active() && !mWritten) record(frame, "shadows.clear", {});
}

} // namespace tessera::backends
