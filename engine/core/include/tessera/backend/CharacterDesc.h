#pragma once
/// @file CharacterDesc.h
/// The characters the host asks a backend to upload, and how to draw them.

#include "tessera/backend/Handles.h"
#include "tessera/scene/Aabb.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

namespace tessera::character {
struct CharacterAsset;
}

namespace tessera::backend {

/// Upload description. The asset stays owned by the engine and must outlive
/// the handle (backends upload what they need at creation and keep no
/// pointer into it afterwards).
struct CharacterDesc {
    const character::CharacterAsset* asset = nullptr;
    /// The character's compression box (the paper's "bounding box local to
    /// each character"): model-space bounds that contain every skinned cage
    /// position the character will be drawn with, e.g.
    /// character::animatedBounds. Positions outside it are clamped.
    scene::Aabb box;
};

/// How the control cage is animated (the paper's "Rendering Animated,
/// Tessellated Characters").
enum class CharacterPath : uint8_t {
    /// Pass 1 skins each cage vertex once into the 128-bit compressed vertex
    /// (CompressedVertex.h) through the backend's own recirculation (compute,
    /// transform feedback, or render target + R2VB); pass 2 tessellates and
    /// fetches one compressed vertex per superprimitive vertex.
    TwoPass,
    /// No pre-pass: every tessellated vertex skins the three cage vertices of
    /// its triangle itself (the paper's brute-force baseline).
    SinglePass,
};

const char* toString(CharacterPath path);

/// One character instance to draw this frame.
struct CharacterDrawItem {
    CharacterHandle character;
    glm::mat4 world{1.0f};  ///< model to world
    /// Skinning palette: global(node) * inverseBind for each of the asset's
    /// CageMesh::bindings, in model space (character::Pose::palette).
    std::span<const glm::mat4> palette;
    /// Continuous tessellation level for the whole draw (the paper's
    /// per-draw level); clamped to [1, the backend's maximum].
    float tessLevel = 1.0f;
    /// The LOD tier it is drawn in (TS_LOD_NEAR, _MIDDLE, _FAR of
    /// CrowdLod.h; lod::LodManager's choice). Only the near tier is
    /// tessellated and displaced; the others draw the cage at level 1 with
    /// the normal map.
    uint32_t tier = 0;
    /// Share of the instance this draw covers during a LOD cross-fade, in
    /// (0, 1] (lod::LodDraw::coverage), and whether it is the copy of the
    /// tier the instance fades out of.
    float coverage = 1.0f;
    bool fadingOut = false;
};

struct CharacterDrawInfo {
    std::span<const CharacterDrawItem> items;
    CharacterPath path = CharacterPath::TwoPass;
    /// Displace along the interpolated normal by the asset's displacement map
    /// (when it has one); false draws the interpolated cage surface.
    bool displacement = true;
    /// Tint each instance by its LOD tier (--lod-colors).
    bool lodColors = false;
};

} // namespace tessera::backend
