#include "common/GpuCharacter.h"

#include "common/MipImage.h"

#include "tessera/character/CharacterAsset.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <glm/gtc/matrix_inverse.hpp>

namespace tessera::backends {
namespace {

using character::TextureFormat;
using character::TextureImage;

gpu::Image makeImage(gpu::Device& device, const TextureImage& texture, VkFormat format, const std::string& name) {
    gpu::ImageDesc desc;
    desc.width = texture.width;
    desc.height = texture.height;
    desc.format = format;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.name = name;
    gpu::Image image(device, desc);
    image.upload(std::as_bytes(std::span(texture.bytes)), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    return image;
}

// An RGBA8 map with its whole mip chain: a creature a few dozen pixels tall
// samples a 1,024-texel map at a sixteenth of its size or less, which
// without mips aliases on any device and, on a CPU rasterizer, reads texels
// scattered over the whole image.
gpu::Image makeMippedImage(gpu::Device& device, const TextureImage& texture, core::MipEncoding encoding,
                           const std::string& name) {
    const std::span<const uint8_t> level0[1] = {texture.bytes};
    return makeMippedRgba8(device, level0, texture.width, texture.height, VK_FORMAT_R8G8B8A8_UNORM, encoding, name);
}

// A 1x1 stand-in for a map the asset lacks, so every draw binds the same
// layout: mid-grey albedo, the flat tangent-space normal, zero displacement.
TextureImage constantTexture(TextureFormat format, std::initializer_list<uint8_t> bytes) {
    TextureImage t;
    t.width = t.height = 1;
    t.format = format;
    t.bytes.assign(bytes);
    return t;
}

uint64_t textureBytes(const gpu::Image& image, uint32_t bytesPerTexel) {
    uint64_t bytes = 0;
    for (uint32_t mip = 0; mip < image.mipLevels(); ++mip)
        bytes += uint64_t(std::max(1u, image.width() >> mip)) * std::max(1u, image.height() >> mip) * bytesPerTexel;
    return bytes;
}

} // namespace

Result<std::unique_ptr<GpuCharacter>> GpuCharacter::create(gpu::Device& device, const backend::CharacterDesc& desc,
                                                           VkBufferUsageFlags compressedUsage) {
    if (!desc.asset) return Error{"createCharacter: no asset"};
    const character::CharacterAsset& asset = *desc.asset;
    const character::CageMesh& cage = asset.cage;
    const std::string name = asset.name.empty() ? std::string("character") : asset.name;
    if (cage.vertices.empty() || cage.triangleCount() == 0) return Error{name + ": the cage has no triangles"};
    if (cage.bindings.empty()) return Error{name + ": the cage has no skinning palette"};
    if (cage.bindings.size() > TS_MAX_CHARACTER_JOINTS)
        return Error{name + ": " + std::to_string(cage.bindings.size()) + " skinning matrices, more than the " +
                     std::to_string(TS_MAX_CHARACTER_JOINTS) + " a character may have"};
    for (uint32_t index : cage.indices)
        if (index >= cage.vertices.size())
            return Error{name + ": triangle index " + std::to_string(index) + " out of range (" +
                         std::to_string(cage.vertices.size()) + " vertices)"};
    const uint64_t texels = uint64_t(cage.vertices.size()) * TS_CHARACTER_VERTEX_TEXELS;
    const uint32_t limit = device.properties().limits.maxTexelBufferElements;
    if (texels > limit)
        return Error{name + ": a cage of " + std::to_string(cage.vertices.size()) + " vertices needs " +
                     std::to_string(texels) + " texels, more than this device's maxTexelBufferElements (" +
                     std::to_string(limit) + ")"};
    if (desc.box.isEmpty()) return Error{name + ": empty compression box"};

    std::unique_ptr<GpuCharacter> c(new GpuCharacter());
    c->mDevice = &device;
    c->mName = name;
    c->mVertexCount = static_cast<uint32_t>(cage.vertices.size());
    c->mTriangleCount = cage.triangleCount();
    c->mPaletteSize = static_cast<uint32_t>(cage.bindings.size());
    c->mCompressedUsage = compressedUsage;
    // A degenerate box axis (a flat model) would divide by zero when packing.
    const glm::vec3 pad = glm::max(desc.box.extents() * 1e-4f, glm::vec3(1e-5f));
    c->mBoxMin = desc.box.min - pad;
    c->mBoxMax = desc.box.max + pad;

    auto converted = convertVertices(cage, cage.bindings.size(), name);
    if (!converted) return converted.error();
    const std::vector<shader::CharacterVertex>& gpuVertices = converted.value();
    glm::vec2 uvMin(FLT_MAX), uvMax(-FLT_MAX);
    size_t negative = 0;
    for (const character::CageVertex& v : cage.vertices) {
        uvMin = glm::min(uvMin, v.uv);
        uvMax = glm::max(uvMax, v.uv);
        negative += v.tangent.w < 0.0f ? 1 : 0;
    }
    // The compressed uv is 16-bit fixed point over the cage's own uv range.
    uvMax = glm::max(uvMax, uvMin + glm::vec2(1e-6f));
    c->mUvRange = glm::vec4(uvMin, uvMax);
    // The compressed vertex has no bitangent sign; the character's majority
    // sign stands in (generated creatures are all +1; see docs/CHARACTERS.md).
    c->mNegativeHandedness = negative * 2 > cage.vertices.size();

    const VkDeviceSize vertexBytes = gpuVertices.size() * sizeof(shader::CharacterVertex);
    c->mVertices = gpu::Buffer(device, vertexBytes,
                               VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                   VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                               gpu::MemoryUsage::GpuOnly, name + ".cageVertices");
    c->mVertices.upload(std::span<const shader::CharacterVertex>(gpuVertices));
    c->mVertexTexels = gpu::BufferView(device, c->mVertices, VK_FORMAT_R32G32B32A32_UINT, 0, vertexBytes,
                                       name + ".cageVertexTexels");
    c->mIndices = gpu::Buffer(device, cage.indices.size() * sizeof(uint32_t),
                              VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              gpu::MemoryUsage::GpuOnly, name + ".cageIndices");
    c->mIndices.upload(std::span<const uint32_t>(cage.indices));
    c->mGpuVertices = gpuVertices;
    c->mCageIndices = cage.indices;

    const TextureImage grey = constantTexture(TextureFormat::Rgba8, {150, 150, 150, 255});
    const TextureImage flat = constantTexture(TextureFormat::Rgba8, {128, 128, 255, 255});
    const TextureImage zero = constantTexture(TextureFormat::R16, {0, 0});
    auto usable = [](const std::optional<TextureImage>& t, TextureFormat f) {
        return t && !t->empty() && t->format == f && t->bytes.size() == size_t(t->width) * t->height * t->bytesPerTexel();
    };
    // UNORM, not SRGB: the frame is lit and stored in display space (an UNORM
    // target, no output transfer), as the terrain's colours are; decoding
    // the albedo to linear here would darken characters against the terrain.
    c->mHasNormalMap = usable(asset.normalMap, TextureFormat::Rgba8);
    // Mips of the base colour averaged in linear light (its bytes are sRGB,
    // glTF's rule), of the normal map as stored (the shader normalises).
    c->mBaseColor = makeMippedImage(device, usable(asset.baseColor, TextureFormat::Rgba8) ? *asset.baseColor : grey,
                                    core::MipEncoding::Srgb, name + ".baseColor");
    c->mNormalMap = makeMippedImage(device, usable(asset.normalMap, TextureFormat::Rgba8) ? *asset.normalMap : flat,
                                    core::MipEncoding::Linear, name + ".normalMap");
    const bool displaced = asset.displacement && usable(std::optional<TextureImage>(asset.displacement->image),
                                                        TextureFormat::R16);
    c->mHasDisplacement = displaced;
    if (displaced) {
        c->mDisplacementScale = asset.displacement->scale;
        c->mDisplacementBias = asset.displacement->bias;
    }
    c->mDisplacement = makeImage(device, displaced ? asset.displacement->image : zero, VK_FORMAT_R16_UNORM,
                                 name + ".displacementMap");
    // Within the nearest mip on a CPU rasterizer (half the texels trilinear
    // filtering reads; docs/LOOKS.md, "Detail textures on a CPU rasterizer"),
    // trilinear on a GPU. The displacement map is read at mip 0 only.
    c->mSampler = gpu::Sampler(device, VK_FILTER_LINEAR,
                               device.features().isCpu ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR,
                               VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, name + ".sampler");
    c->mStaticBytes = vertexBytes + c->mIndices.size() + textureBytes(c->mBaseColor, 4) +
                      textureBytes(c->mNormalMap, 4) + textureBytes(c->mDisplacement, 2);
    return c;
}

Result<std::vector<shader::CharacterVertex>> GpuCharacter::convertVertices(const character::CageMesh& mesh,
                                                                            size_t paletteSize,
                                                                            const std::string& name) {
    std::vector<shader::CharacterVertex> gpuVertices(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const character::CageVertex& v = mesh.vertices[i];
        for (int k = 0; k < 4; ++k)
            if (v.weights[k] > 0.0f && v.joints[k] >= paletteSize)
                return Error{name + ": vertex " + std::to_string(i) + " uses joint " + std::to_string(v.joints[k]) +
                             " of " + std::to_string(paletteSize)};
        shader::CharacterVertex& g = gpuVertices[i];
        g.positionU = glm::vec4(v.position, v.uv.x);
        g.normalV = glm::vec4(v.normal, v.uv.y);
        g.tangent = v.tangent;
        // Unused influences may hold any index; point them at joint 0 so the
        // shader never reads past the palette.
        g.joints = glm::uvec4(v.weights.x > 0.0f ? v.joints.x : 0, v.weights.y > 0.0f ? v.joints.y : 0,
                              v.weights.z > 0.0f ? v.joints.z : 0, v.weights.w > 0.0f ? v.joints.w : 0);
        // Normalised here, once, as character::skinVertex normalises per
        // vertex: glTF only promises sums near 1. A vertex with no weight
        // follows joint 0 (the CPU reference keeps it in place; the loader
        // gives every skinless mesh one identity joint, so the two agree).
        const float sum = v.weights.x + v.weights.y + v.weights.z + v.weights.w;
        g.weights = sum > 0.0f ? v.weights / sum : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    }
    return gpuVertices;
}

CompressedCage& GpuCharacter::compressed(uint32_t slot, uint32_t instance) {
    auto& caches = mCompressed[slot];
    while (caches.size() <= instance) {
        auto cage = std::make_unique<CompressedCage>();
        const std::string tag = mName + ".compressed[" + std::to_string(slot) + "][" + std::to_string(caches.size()) + "]";
        // Rounded up to whole rows of the r2vb target (at most 256 texels
        // wide), so a render-target copy never writes past the end.
        const VkDeviceSize texels = (VkDeviceSize(mVertexCount) + 255) / 256 * 256;
        cage->buffer = gpu::Buffer(*mDevice, texels * 16, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | mCompressedUsage,
                                   gpu::MemoryUsage::GpuOnly, tag);
        cage->view = gpu::BufferView(*mDevice, cage->buffer, VK_FORMAT_R32G32B32A32_UINT, 0, texels * 16, tag + ".texels");
        caches.push_back(std::move(cage));
    }
    return *caches[instance];
}

shader::CharacterUniforms GpuCharacter::uniforms(const glm::mat4& world, float level, bool displacement,
                                                 const glm::vec4& lod) const {
    shader::CharacterUniforms u{};
    u.world = world;
    u.worldNormal = glm::inverseTranspose(world);
    u.boxMin = glm::vec4(mBoxMin, 0.0f);
    u.boxMax = glm::vec4(mBoxMax, 0.0f);
    u.uvRange = mUvRange;
    const bool on = displacement && mHasDisplacement;
    u.displacement = glm::vec4(on ? mDisplacementScale : 0.0f, on ? mDisplacementBias : 0.0f, level, 1.0f);
    u.counts = glm::uvec4(mVertexCount, mPaletteSize, 256u, mNegativeHandedness ? 1u : 0u);
    u.lod = lod;
    return u;
}

void GpuCharacter::useCageVertexStream(gpu::GraphicsPipelineDesc& desc) {
    using shader::CharacterVertex;
    constexpr VkFormat kFloat4 = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.vertexBindings = {{0, sizeof(CharacterVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, kFloat4, offsetof(CharacterVertex, positionU)},
                             {1, 0, kFloat4, offsetof(CharacterVertex, normalV)},
                             {2, 0, kFloat4, offsetof(CharacterVertex, tangent)},
                             {3, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(CharacterVertex, joints)},
                             {4, 0, kFloat4, offsetof(CharacterVertex, weights)}};
}

} // namespace tessera::backends
