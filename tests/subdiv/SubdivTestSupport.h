#pragma once
// Helpers shared by the subdivision tests: which base face and sub-face a
// ptex face belongs to, patch-local to ptex coordinates, angles, and the
// list of shapes every surface test runs over.

#include "ObjShapeTestFiles.h"
#include "TestShapes.h"

#include "tessera/subdiv/SubdivSurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace tessera::subdiv::test {

/// The base face and sub-face of a ptex face.
struct PtexOwner {
    uint32_t face = 0;
    uint32_t subFace = 0;
};

inline std::vector<PtexOwner> ptexOwners(const SubdivSurface& surface) {
    std::vector<PtexOwner> owners(surface.ptexFaceCount());
    for (uint32_t f = 0; f < surface.baseFaceCount(); ++f) {
        uint32_t count = surface.baseFaceSize(f) == 4 ? 1 : surface.baseFaceSize(f);
        for (uint32_t k = 0; k < count; ++k) owners[surface.firstPtexFace(f) + k] = {f, k};
    }
    return owners;
}

/// Patch-local (s, t) to the patch's ptex-face (u, v) (exact in double).
inline glm::dvec2 ptexCoord(const PatchParam& param, glm::dvec2 st) {
    return (glm::dvec2(param.u(), param.v()) + st) * param.paramFraction();
}

inline double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
    double s = glm::length(glm::cross(a, b)), c = glm::dot(a, b);
    return std::atan2(s, c) * 180.0 / std::numbers::pi;
}

/// Builds `shape`; an error fails the test (as an exception GoogleTest
/// reports, since the caller cannot go on without a surface).
inline SubdivSurface build(const ObjShape& shape, const SubdivSettings& settings = {}) {
    Result<SubdivSurface> surface = SubdivSurface::create(shape, settings);
    if (!surface.ok()) throw std::runtime_error(surface.error().message);
    return std::move(surface).value();
}

/// OpenSubdiv's regression shapes (shared/testdata/osd_shapes), read with
/// the .obj reader and named by their file names.
inline std::vector<ObjShape> fileShapes() {
    std::vector<ObjShape> shapes;
    for (const std::filesystem::path& path : tessera::test::osdShapeFiles()) {
        Result<ObjShape> shape = readObjShape(path);
        if (!shape.ok()) throw std::runtime_error(shape.error().message);
        shape->name = path.filename().string();
        shapes.push_back(std::move(shape).value());
    }
    return shapes;
}

/// The shapes every surface-wide test covers: the in-code ones and
/// OpenSubdiv's regression shapes.
inline std::vector<ObjShape> allShapes() {
    std::vector<ObjShape> shapes = codeShapes();
    for (ObjShape& shape : fileShapes()) shapes.push_back(std::move(shape));
    return shapes;
}

} // namespace tessera::subdiv::test
