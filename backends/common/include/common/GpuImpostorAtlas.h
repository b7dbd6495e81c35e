#pragma once
/// @file GpuImpostorAtlas.h
/// A crowd's impostor tier images on the GPU (layout in CrowdImpostor.h):
/// every creature's layers (character::ImpostorAtlas, one per baked clip
/// and phase) concatenated in the order of the crowd's global baked clips,
/// so that an instance's first layer is its global clip (ids.z) times
/// TS_IMPOSTOR_PHASES, in two 2D-array images of TS_IMPOSTOR_MIPS levels:
/// base colour and coverage (R8G8B8A8_SRGB, so filtering blends linear
/// colour) and the model-space normal (R8G8B8A8_UNORM); with the sampler
/// the cards read both through (linear between texels and mips, clamped).
/// Bound at TS_BINDING_CROWD_IMPOSTOR_ALBEDO and _NORMAL (CrowdDescriptors).

#include "tessera/backend/CrowdDesc.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <cstdint>

namespace tessera::backends {

class GpuImpostorAtlas {
public:
    GpuImpostorAtlas() = default;
    /// Uploads the atlases of `desc`. An atlas holding a clip per baked clip
    /// (the rest pose first) maps layer for layer; one holding its asset's
    /// clips only (the rest pose not baked) fills the rest pose's layers
    /// with its first clip's first phase. A creature without a usable atlas
    /// gets clear layers (coverage 0: its cards show no pixel); a crowd with
    /// none at all gets one small clear clip, which every layer index
    /// clamps to.
    static GpuImpostorAtlas create(gpu::Device& device, const backend::CrowdDesc& desc);

    VkDescriptorImageInfo albedo() const;
    VkDescriptorImageInfo normal() const;
    /// The images themselves (for the tests' readback).
    const gpu::Image& albedoImage() const { return mAlbedo; }
    const gpu::Image& normalImage() const { return mNormal; }
    /// Device bytes of both images, every mip.
    uint64_t bytes() const { return mBytes; }
    /// Per creature and view cell (tsCrowdImpostorBoundsWord) the rectangle
    /// its layers cover there (tsImpostorPackBounds), with a texel to spare
    /// for filtering; 0 (an empty card) where it covers nothing or has no
    /// atlas. Goes to CrowdUniforms::impostorBounds.
    const std::array<uint32_t, TS_CROWD_MAX_CHARACTERS * TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS>& bounds() const {
        return mBounds;
    }

private:
    gpu::Image mAlbedo, mNormal;
    gpu::Sampler mSampler;
    uint64_t mBytes = 0;
    std::array<uint32_t, TS_CROWD_MAX_CHARACTERS * TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS> mBounds{};
};

} // namespace tessera::backends
