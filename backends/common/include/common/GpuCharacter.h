#pragma once
/// @file GpuCharacter.h
/// A character's GPU resources shared by the backends: the bind-pose cage
/// (CharacterVertex, shader::CharacterUniforms' layout), its triangle list,
/// its maps, and the animated, compressed cage each drawn instance gets per
/// frame (the paper's 128-bit vertices, CompressedVertex.h). What a
/// backend's technique keeps per character is its TechniqueExtension.

#include "common/TechniqueExtension.h"
#include "tessera/shaders/CharacterUniforms.h"
#include "tessera/backend/CharacterDesc.h"
#include "tessera/character/CageMesh.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessera::backends {

/// One instance's animated cage: a uvec4 per cage vertex, plus an RGBA32UI
/// texel view of it for the evaluation vertex shaders of the emulated backends.
struct CompressedCage {
    gpu::Buffer buffer;
    gpu::BufferView view;
};

class GpuCharacter : public ExtensionSlot {
public:
    /// Extra usage the backend's pass 1 needs on the compressed buffers
    /// (storage for compute, transform feedback, transfer destination for R2VB).
    static Result<std::unique_ptr<GpuCharacter>> create(gpu::Device& device, const backend::CharacterDesc& desc,
                                                        VkBufferUsageFlags compressedUsage);

    const std::string& name() const { return mName; }
    uint32_t vertexCount() const { return mVertexCount; }
    uint32_t triangleCount() const { return mTriangleCount; }
    uint32_t paletteSize() const { return mPaletteSize; }

    /// Bind-pose cage: vertex stream (stride 80, useCageVertexStream),
    /// storage buffer, and an RGBA32UI texel view
    /// (TS_CHARACTER_VERTEX_TEXELS texels per vertex).
    gpu::Buffer& vertices() { return mVertices; }
    VkBufferView vertexTexels() const { return mVertexTexels.handle(); }
    /// Three uint32 per triangle: the index buffer, and the per-instance
    /// stream of superprimitive vertex indices for the emulated draws.
    gpu::Buffer& indices() { return mIndices; }

    /// The animated cage for the `instance`-th draw of this character in the
    /// frame slot `slot` (made on first use, kept for later frames).
    CompressedCage& compressed(uint32_t slot, uint32_t instance);

    /// Uniforms for one instance: placement, level, displacement on or off,
    /// and its LOD tier and cross-fade (CharacterUniforms::lod).
    shader::CharacterUniforms uniforms(const glm::mat4& world, float level, bool displacement,
                                       const glm::vec4& lod) const;

    gpu::Image& baseColor() { return mBaseColor; }
    gpu::Image& normalMap() { return mNormalMap; }
    gpu::Image& displacementMap() { return mDisplacement; }
    gpu::Sampler& sampler() { return mSampler; }
    bool hasDisplacement() const { return mHasDisplacement; }

    /// Bytes of the cage, index and map resources (not the per-frame caches).
    uint64_t staticBytes() const { return mStaticBytes; }

    /// What an instanced crowd copies into its own buffers and records: the
    /// cage as the GPU reads it, its triangles, and the numbers
    /// CharacterUniforms carries for a single draw.
    const std::vector<shader::CharacterVertex>& gpuVertices() const { return mGpuVertices; }
    const std::vector<uint32_t>& cageIndices() const { return mCageIndices; }
    glm::vec3 boxMin() const { return mBoxMin; }
    glm::vec3 boxMax() const { return mBoxMax; }
    glm::vec4 uvRange() const { return mUvRange; }
    bool negativeHandedness() const { return mNegativeHandedness; }
    float displacementScale() const { return mHasDisplacement ? mDisplacementScale : 0.0f; }
    float displacementBias() const { return mHasDisplacement ? mDisplacementBias : 0.0f; }
    bool hasNormalMap() const { return mHasNormalMap; }

    /// Makes binding 0 of `desc` a cage as a vertex stream: stride
    /// sizeof(shader::CharacterVertex), locations 0 to 4 position and u,
    /// normal and v, tangent, joints, weights (the skinning passes that read
    /// the cage as vertices).
    static void useCageVertexStream(gpu::GraphicsPipelineDesc& desc);

    /// A cage (or a mesh sharing its bindings, such as the far mesh) as the
    /// GPU reads it: weights normalised, unused joints pointed at 0. Fails
    /// naming `name` when a vertex uses a joint past `paletteSize`.
    static Result<std::vector<shader::CharacterVertex>> convertVertices(const character::CageMesh& mesh,
                                                                        size_t paletteSize, const std::string& name);

private:
    GpuCharacter() = default;

    gpu::Device* mDevice = nullptr;
    std::string mName;
    uint32_t mVertexCount = 0;
    uint32_t mTriangleCount = 0;
    uint32_t mPaletteSize = 0;
    bool mHasDisplacement = false;
    bool mNegativeHandedness = false;
    float mDisplacementScale = 0.0f;
    float mDisplacementBias = 0.0f;
    glm::vec3 mBoxMin{0.0f};
    glm::vec3 mBoxMax{1.0f};
    glm::vec4 mUvRange{0.0f, 0.0f, 1.0f, 1.0f};
    VkBufferUsageFlags mCompressedUsage = 0;
    uint64_t mStaticBytes = 0;
    bool mHasNormalMap = false;
    std::vector<shader::CharacterVertex> mGpuVertices;
    std::vector<uint32_t> mCageIndices;

    gpu::Buffer mVertices;
    gpu::BufferView mVertexTexels;
    gpu::Buffer mIndices;
    gpu::Image mBaseColor;
    gpu::Image mNormalMap;
    gpu::Image mDisplacement;
    gpu::Sampler mSampler;
    std::array<std::vector<std::unique_ptr<CompressedCage>>, gpu::kFramesInFlight> mCompressed;
};

} // namespace tessera::backends
