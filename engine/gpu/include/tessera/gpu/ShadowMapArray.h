#pragma once
/// @file ShadowMapArray.h
/// The depth maps of a cascaded shadow map: one layer per cascade, rendered
/// one at a time by depth-only passes and sampled as one array with
/// hardware depth comparison.

#include "tessera/gpu/Image.h"
#include "tessera/gpu/Sampler.h"
#include "tessera/gpu/UniqueHandle.h"

#include <string>
#include <vector>

namespace tessera::gpu {

class Device;

/// A `size` x `size` x `layers` D32 depth array (docs/LOOKS.md, "Cascaded
/// shadow maps"): a 2D view of each layer to render the cascade into, a
/// 2D-array view over all of them and a comparison sampler (LESS_OR_EQUAL,
/// bilinear: hardware 2x2 percentage-closer filtering; outside the map: lit)
/// for a `sampler2DArrayShadow`. Every object is named after `name`.
///
/// A frame's use: beginWriting, then for each cascade beginLayer (cleared to
/// depth 1), the casters' depth-only draws, endLayer; then endWriting, which
/// hands every layer to the given shader stages. Later casters in the same
/// frame (a crowd after the characters) write again with Contents::Keep,
/// adding their depths to the layers' instead of clearing them. Between frames and from
/// creation (cleared to depth 1, so nothing is shadowed) the layers are in
/// SHADER_READ_ONLY_OPTIMAL, so a frame that draws no casters still samples
/// a valid, fully lit map.
class ShadowMapArray {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT;

    /// What a write does with the layers' depths: the frame's first write
    /// clears them, later ones keep and add to them.
    enum class Contents { Clear, Keep };

    ShadowMapArray() = default;
    /// Makes the image, its views and sampler, and clears every layer
    /// (blocking: creation time only).
    ShadowMapArray(Device& device, uint32_t size, uint32_t layers, const std::string& name);
    ~ShadowMapArray() { mLayerViews.clear(); }
    ShadowMapArray(ShadowMapArray&&) noexcept = default;
    ShadowMapArray& operator=(ShadowMapArray&&) noexcept = default;

    bool valid() const { return mImage.valid(); }
    uint32_t size() const { return mImage.width(); }
    uint32_t layers() const { return mImage.arrayLayers(); }
    /// Device bytes of the depth texels.
    uint64_t bytes() const { return uint64_t(size()) * size() * layers() * 4u; }

    /// Transitions every layer for depth writes, after earlier reads by
    /// `readStages` (the previous frame's sampling, or this frame's where
    /// `contents` is Keep, whose depths the transition then preserves).
    void beginWriting(VkCommandBuffer cmd, VkPipelineStageFlags2 readStages,
                      Contents contents = Contents::Clear) const;
    /// Begins depth-only dynamic rendering into `layer`, cleared to 1 or
    /// loaded (`contents`), with the whole layer as viewport and scissor.
    void beginLayer(VkCommandBuffer cmd, uint32_t layer, Contents contents = Contents::Clear) const;
    void endLayer(VkCommandBuffer cmd) const;
    /// Hands every layer to sampled reads by `readStages`.
    void endWriting(VkCommandBuffer cmd, VkPipelineStageFlags2 readStages) const;

    /// The array view with the comparison sampler, for a combined image
    /// sampler binding, in SHADER_READ_ONLY_OPTIMAL.
    VkDescriptorImageInfo descriptor() const;

private:
    // The 2D-array view over every layer, then one 2D view per layer;
    // released before the image (the destructor clears them; a move
    // assignment moves them first).
    std::vector<UniqueHandle<VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW>> mLayerViews;
    Image mImage;
    Sampler mSampler;
};

} // namespace tessera::gpu
