#pragma once
/// @file LodPolicy.h
/// How the LOD manager sorts instances into tiers and what a frame may cost:
/// thresholds in projected pixels, hysteresis, cross-fade length and the
/// frame budget, with defaults per device class.

#include "tessera/core/Result.h"

#include <cstdint>
#include <limits>

namespace tessera::lod {

/// What a frame may draw. Counts include the copies a cross-fade draws.
struct LodBudget {
    static constexpr uint32_t kUnlimited = std::numeric_limits<uint32_t>::max();
    /// Instances drawn tessellated (the near tier).
    uint32_t maxNearInstances = 256;
    /// Triangles the near tier's tessellation makes in one frame. When even
    /// the largest instance alone would exceed it, the frame's level cap
    /// comes down until it fits (to the bare cage, level 1).
    uint64_t maxTessellatedTriangles = 24'000'000;
    /// Instances drawn as their untessellated cage (the middle tier).
    uint32_t maxMiddleInstances = 16384;
    /// Instances drawn with the far mesh; the smallest beyond it are drawn
    /// as impostors (kUnlimited: all). The impostor tier has no budget: a
    /// card costs two triangles and a few pixels.
    uint32_t maxFarInstances = kUnlimited;
};

/// The kind of device the budget's defaults are made for.
enum class DeviceClass {
    Gpu, ///< a hardware GPU
    Cpu, ///< a software rasterizer (lavapipe): stays interactive, under a second a frame
};

struct LodPolicy {
    /// An instance whose bounding sphere covers at least this many pixels
    /// on screen (its diameter) is tessellated; below `farPixels` it takes
    /// the far mesh; in between, the middle tier.
    float nearPixels = 192.0f;
    float farPixels = 64.0f;
    /// Below this many pixels an instance is drawn as an impostor (a card
    /// from its baked views, shaders/CrowdImpostor.h); 0: only when the far
    /// budget is spent. At most `farPixels`.
    float impostorPixels = 32.0f;
    /// An instance goes back to a coarser tier only this fraction below the
    /// threshold it crossed, so one on a boundary does not flicker.
    float hysteresis = 0.15f;
    /// Frames a tier change cross-fades over (dithered), 0 for none; at
    /// most TS_LOD_MAX_FADE_FRAMES.
    uint32_t fadeFrames = 8;
    /// A tessellated edge covers about this many pixels (the near tier's
    /// level follows the instance's size on screen, as the paper's per-draw
    /// level; fixedLevel overrides it).
    float targetEdgePixels = 2.0f;
    /// Forces every near instance's level (--character-level), for
    /// measurements; the triangle budget still caps it. 0: from the size.
    float fixedLevel = 0.0f;
    /// The far tier's mesh: at most this many triangles (the content's far
    /// mesh simplified further when it has more); 0 keeps the content's.
    uint32_t farMeshTriangles = 120;
    /// The middle tier's mesh: the cage's own vertices with its triangles
    /// simplified to at most this many (the normal map keeps the surface);
    /// 0 draws the whole cage.
    uint32_t middleMeshTriangles = 0;
    /// The far tier's shadow casters (the cascaded shadow maps' depth-only
    /// passes): the far mesh's own vertices with its triangles simplified to
    /// at most this many; 0 casts the far mesh itself (as the middle tier's
    /// casters do). A far creature is a few pixels tall and its shadow a few
    /// texels of a cascade; the casters' vertex work, paid again in every
    /// cascade, is most of what shadows cost a crowd (docs/LOOKS.md, "The
    /// cost and auto").
    uint32_t farCasterTriangles = 96;
    /// Instances the terrain hides from the eye are culled (tsLodBehindTerrain,
    /// against LodView::occluders).
    bool horizonCulling = true;
    LodBudget budget;

    /// The defaults for `device`: on a CPU rasterizer a handful of
    /// tessellated instances and a few thousand far ones.
    static LodPolicy forDevice(DeviceClass device);

    /// Refuses thresholds and budgets that cannot work (a budget of zero,
    /// a far threshold above the near one, ...), with one line naming the
    /// setting.
    Status validate() const;
};

} // namespace tessera::lod
