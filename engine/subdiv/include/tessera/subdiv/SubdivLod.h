#pragma once
/// @file SubdivLod.h
/// Level of detail for a subdivision surface on the CPU: the uniforms a
/// backend draws it with this frame, and the CPU reference of what the GPU
/// will tessellate (the same shared functions of SubdivLayout.h: per-corner
/// levels from projected size, domain levels, culling), which also enforces
/// the frame's triangle budget by scaling every level down, so no view of a
/// large or close model costs more than the budget allows.

#include "tessera/shaders/SubdivLayout.h"
#include "tessera/scene/Frustum.h"
#include "tessera/subdiv/SubdivGpuMesh.h"

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// How a surface is drawn: level of detail, budget, displacement, shading.
struct SubdivLodSettings {
    /// Screen-space target: pixels per tessellated segment.
    float targetPixels = 6.0f;
    /// Highest level (the backend's: 64 in hardware, 14.99 emulated).
    float levelCap = 64.0f;
    /// Most triangles one draw may generate (0: unlimited); levels are
    /// scaled down uniformly until the prediction fits.
    uint64_t triangleBudget = 0;
    /// A level forced on every domain, for measurements (0: adaptive).
    float fixedLevel = 0.0f;
    /// Select displacement mip levels from the levels (section 6); off
    /// samples the finest level everywhere.
    bool mipSelection = true;
    uint32_t normals = TS_SUBDIV_NORMALS_APPROXIMATE;
    uint32_t view = TS_SUBDIV_VIEW_SHADED;
    /// Object units per unit of D; 0 draws the base surface.
    float displacementScale = 0.0f;
    /// The largest |D| of the tiles (their units), for culling bounds.
    float maxDisplacement = 0.0f;
    glm::vec3 albedo{0.72f, 0.66f, 0.58f};
};

/// The view a surface is drawn from.
struct SubdivView {
    scene::Frustum frustum;
    glm::vec3 eye{0.0f};
    /// Viewport height * projection[1][1] / 2: pixels one metre covers
    /// face-on at one metre.
    float pixelsPerMetre = 1.0f;
};

/// What the CPU reference predicts for one draw.
struct SubdivPrediction {
    uint32_t domainsVisible = 0;
    /// Triangles the tessellator will generate (fractional-odd quads at the
    /// predicted levels, every visible domain).
    uint64_t triangles = 0;
};

struct SubdivLodFrame {
    shader::SubdivUniforms uniforms{};
    SubdivPrediction prediction;
    /// The factor the budget scaled every level by (1: none).
    float budgetScale = 1.0f;
};

class SubdivLod {
public:
    /// This frame's uniforms for `mesh` with base vertices `base` placed by
    /// `model`, seen from `view`, and the prediction they give (within the
    /// budget when there is one, down to level 1 everywhere).
    static SubdivLodFrame plan(const SubdivGpuMesh& mesh, std::span<const glm::vec3> base, const glm::mat4& model,
                               const SubdivView& view, const SubdivLodSettings& settings);
    /// The CPU reference: what a draw with `uniforms` tessellates, given
    /// the refined points (all of them, SubdivGpuMesh::refine's layout).
    static SubdivPrediction predict(const SubdivGpuMesh& mesh, std::span<const glm::vec4> refined,
                                    const shader::SubdivUniforms& uniforms);
};

} // namespace tessera::subdiv
