#pragma once
/// @file LodInstance.h
/// What the LOD manager reads per instance, per character and per view.

#include "tessera/shaders/CrowdLod.h"
#include "tessera/scene/Camera.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

namespace tessera::lod {

/// One drawable instance (an agent, a placed character).
struct LodInstance {
    /// World bounding sphere (xyz centre, w radius) holding the instance in
    /// any pose it may take.
    glm::vec4 sphere{0.0f, 0.0f, 0.0f, 1.0f};
    /// Stable id: the key of the instance's LOD state from frame to frame
    /// (agents are re-sorted in memory; their ids stay). Below 2^24.
    uint32_t id = 0;
    /// Index into the frame's characters (LodCharacter).
    uint32_t character = 0;
};

/// What a tier costs for one character.
struct LodCharacter {
    /// Near-tier level per projected pixel of the bounding sphere's
    /// diameter: (mean cage edge / sphere diameter) / targetEdgePixels, so
    /// an edge covers about targetEdgePixels on screen (levelPerPixelFor()).
    float levelPerPixel = 0.01f;
    uint32_t cageTriangles = 0;   ///< the near tier's before tessellation
    uint32_t middleTriangles = 0; ///< the middle tier's mesh (the cage, or its simplified triangles)
    uint32_t farTriangles = 0;    ///< the far mesh's

    /// levelPerPixel for a cage whose mean edge is `meanEdge` in a sphere of
    /// radius `radius` (both in the same units).
    static float levelPerPixelFor(float meanEdge, float radius, float targetEdgePixels) {
        return meanEdge / (2.0f * radius) / targetEdgePixels;
    }
};

/// The view a frame is selected for.
struct LodView {
    scene::Frustum frustum;
    glm::vec3 eye{0.0f};
    /// Viewport height / (2 tan(vertical fov / 2)).
    float pixelsPerRadian = 1.0f;
    /// The backend's highest tessellation level (64 hardware, 14.99 emulated).
    float maxLevel = 64.0f;
    /// Horizon occlusion (tsLodBehindTerrain): the lowest drawn height of each
    /// cell of a square grid, row by row (z rows, x within), its min corner
    /// (world x, z) and cell side in `occluderGrid` (x, y, z) and its cells
    /// per side in w; empty (w 0): no occlusion. Must outlive the update.
    std::span<const float> occluders;
    glm::vec4 occluderGrid{0.0f};

    static LodView fromCamera(const scene::Camera& camera, uint32_t viewportHeight, float maxLevel);
};

} // namespace tessera::lod
