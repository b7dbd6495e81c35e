#pragma once
/// @file SubdivDesc.h
/// A Catmull-Clark surface with analytic displacement (the second paper) as
/// the host hands it to a backend: at creation the packed surface
/// (SubdivMeshData) and its displacement tiles; each frame the
/// animated cage and the per-draw uniforms (placement, level of detail,
/// normals). Every backend refines the control points from the cage with
/// its era's recirculation (compute, transform feedback, render target),
/// tessellates the domains with its tessellator and evaluates them with the
/// shared subdiv_eval.glsl (docs/SUBDIV.md).

#include "tessera/backend/Handles.h"
#include "tessera/backend/SubdivMeshData.h"
#include "tessera/shaders/SubdivLayout.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::backend {

struct SubdivTag;
/// A surface made with Backend::createSubdiv.
using SubdivHandle = Handle<SubdivTag>;

/// Displacement tiles as plain data (subdiv::DisplacementTiles' texture
/// and records, DisplacementTile.h's layout).
struct SubdivTileData {
    /// The packed R32F texture, row-major, width * height texels (empty:
    /// no displacement).
    std::span<const float> texels;
    uint32_t width = 0, height = 0;
    /// One record per ptex face (shader::TileRecord's words).
    std::span<const glm::uvec4> records;
};

struct SubdivDesc {
    /// The packed surface (required). Must outlive createSubdiv only.
    const SubdivMeshData* mesh = nullptr;
    /// Its displacement tiles, one record per ptex face (empty: the base
    /// surface alone). Must outlive createSubdiv only; edits go through
    /// updateSubdivTiles.
    SubdivTileData tiles;
};

/// One frame's draw of a surface.
struct SubdivDrawInfo {
    /// subdiv::SubdivLod::plan's uniforms for this frame's view.
    shader::SubdivUniforms uniforms{};
    /// This frame's base vertices (xyz; the mesh's baseVertexCount), or
    /// empty to keep the last ones (the rest pose at first).
    std::span<const glm::vec4> cage;
};

/// A blocking read of the refined points the last draw used (control
/// points, then corner points, xyz and w), for tests against the CPU.
struct SubdivPoints {
    std::vector<glm::vec4> points;
};

} // namespace tessera::backend
