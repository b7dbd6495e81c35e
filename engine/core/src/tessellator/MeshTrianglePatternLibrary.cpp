#include "tessera/tessellator/MeshTrianglePatternLibrary.h"

#include "EdgeSpacing.h"
#include "RowStitcher.h"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace tessera::tessellator {
namespace {

// Triangles go in the order and winding Tessellator emits them (the
// reference's reversed: Vulkan's counter-clockwise).
constexpr bool kReverseWinding = true;

// An odd-spacing edge with `points` points: only the count and parity shape
// a stitch; the level's fraction only moves points, which the shaders do.
detail::EdgeSpacing oddSpacing(uint32_t points) {
    return detail::EdgeSpacing(detail::toFixed(float(points - 1)), detail::Parity::Odd);
}

std::vector<uint32_t> row(uint32_t first, uint32_t count) {
    std::vector<uint32_t> indices(count);
    std::iota(indices.begin(), indices.end(), first);
    return indices;
}

} // namespace

const MeshTrianglePatternLibrary& MeshTrianglePatternLibrary::uniformFractionalOdd() {
    static const MeshTrianglePatternLibrary library;
    return library;
}

template <typename Stitch>
void MeshTrianglePatternLibrary::add(uint32_t key, uint32_t rowA, uint32_t rowB, Stitch&& stitch) {
    assert(rowA + rowB <= TS_MESH_MAX_VERTICES);
    std::vector<uint32_t> indices;
    detail::RowStitcher stitcher(indices, kReverseWinding);
    stitch(stitcher, row(0, rowA), row(rowA, rowB));
    const auto first = static_cast<uint32_t>(mTriangles.size());
    for (size_t i = 0; i < indices.size(); i += 3)
        mTriangles.push_back(indices[i] | indices[i + 1] << 8 | indices[i + 2] << 16);
    const auto count = static_cast<uint32_t>(mTriangles.size()) - first;
    assert(count <= TS_MESH_MAX_TRIANGLES);
    mKeys[key].entry = {first, count, rowA, rowB};
}

MeshTrianglePatternLibrary::MeshTrianglePatternLibrary() {
    using Rows = const std::vector<uint32_t>&;
    mKeys.resize(TS_MESH_TRI_KEY_COUNT);
    // Transition strips: an outer edge's n points to the first ring's row,
    // which takes the inner spacing's points 1 .. n - 2. At one uniform
    // level the edge and the inner spacing have the same point count.
    for (uint32_t k = 0; k < TS_MESH_TRI_TRANSITION_KEYS; ++k) {
        const uint32_t points = 2 * (k + 2);
        add(k, points, points - 2, [&](detail::RowStitcher& s, Rows a, Rows b) {
            s.transition(a, oddSpacing(points), b, oddSpacing(points));
        });
    }
    // One side of a ring pair: a trapezoid, diagonals mirrored, as
    // TrianglePattern stitches every ring after the first.
    for (uint32_t k = 0; k < TS_MESH_TRI_RING_KEYS; ++k) {
        const uint32_t outside = 2 * (k + 2);
        add(TS_MESH_TRI_KEY_RING + k, outside, outside - 2, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, true, detail::RowStitcher::Diagonals::Mirrored);
        });
    }
    // The centre (or, at level 1, the whole patch): one triangle over the
    // first points of edges 0, 1 and 2.
    add(TS_MESH_TRI_KEY_CENTRE, 3, 0, [](detail::RowStitcher& s, Rows a, Rows) { s.triangle(a[0], a[1], a[2]); });
    buildGroups();
}

void MeshTrianglePatternLibrary::buildGroups() {
    mGroups.resize(TS_MESH_TRI_CLASSES);
    for (uint32_t c = 0; c < TS_MESH_TRI_CLASSES; ++c) {
        // A level whose patch has 2 * (c + 1) points an edge.
        const shader::TsMeshTrianglePatch p = shader::tsMeshTrianglePatch(c == 0 ? 1.0f : float(2 * c + 1));
        const auto first = static_cast<uint32_t>(mGroups.size());
        glm::uvec4 group{0, 0, 0, 0};
        uint32_t patchPoints = 0, patchTriangles = 0;
        for (uint32_t piece = 0; piece < p.pieceCount; ++piece) {
            const glm::uvec4 entry = mKeys[shader::tsMeshTrianglePieceKey(p, piece)].entry;
            const uint32_t points = entry.z + entry.w;
            if (group.y > 0 && (group.z + points > TS_MESH_MAX_VERTICES || group.w + entry.y > TS_MESH_MAX_TRIANGLES)) {
                mGroups.push_back(group);
                group = {piece, 0, 0, 0};
            }
            ++group.y;
            group.z += points;
            group.w += entry.y;
            patchPoints += points;
            patchTriangles += entry.y;
        }
        mGroups.push_back(group);
        const auto groupsPerPatch = static_cast<uint32_t>(mGroups.size()) - first;
        const uint32_t patchesPerGroup =
            groupsPerPatch > 1 ? 1
                               : std::min(TS_MESH_MAX_VERTICES / patchPoints, TS_MESH_MAX_TRIANGLES / patchTriangles);
        mGroups[c] = {first, groupsPerPatch, patchesPerGroup, 0};
    }
}

} // namespace tessera::tessellator
