#pragma once
// SubdivSurface's state: the OpenSubdiv objects the public header hides,
// shared by SubdivSurface's files and BfrReference.

#include "OsdPoint.h"
#include "PatchArrays.h"

#include "tessera/subdiv/SubdivSurface.h"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <string>
#include <vector>

namespace tessera::subdiv {

namespace Far = OpenSubdiv::Far;
/// Far's stencil table at float precision, named without the compatibility
/// subclass Far::StencilTable (see createStencils in SubdivSurface.cpp).
using FloatStencils = Far::StencilTableReal<float>;

struct SubdivSurface::Impl {
    std::string name;
    SubdivSettings settings;
    std::vector<uint32_t> faceSizes;
    std::vector<glm::vec3> basePositions;

    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::unique_ptr<const Far::PatchTable> patchTable;
    /// Null when there are no patches (Far's PatchMap needs one).
    std::unique_ptr<const Far::PatchMap> patchMap;
    /// Base vertices to every control point (refined vertices and local
    /// points), factorized so one application updates everything.
    std::unique_ptr<const FloatStencils> stencils;

    std::vector<uint32_t> firstPtex; ///< per base face, plus the total at the end
    std::vector<glm::vec3> controlPoints;
    std::vector<detail::OsdPoint> scratch; ///< controlPoints as OpenSubdiv writes them
    uint32_t refinedVertexCount = 0;
    uint32_t localPointCount = 0;
    detail::PatchArrays patches;
    scene::Aabb bounds;

    /// Copies `scratch` into controlPoints and recomputes bounds.
    void publishControlPoints();
    /// The patch at ptex (u, v), or -1.
    int findPatch(uint32_t ptexFace, glm::dvec2 uv) const;
    /// Far's basis of `patch` at ptex (u, v) applied to the control points;
    /// derivatives with respect to ptex (u, v).
    LimitPoint evaluate(uint32_t patch, glm::dvec2 uv) const;
};

} // namespace tessera::subdiv
