#include "creature/SubdivBaker.h"

#include "SubdivSampleTable.h"
#include "SurfaceErrorMeter.h"
#include "creature/Bvh.h"
#include "tessera/subdiv/DisplacementConversion.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/PtexTopology.h"
#include "tessera/subdiv/SubdivSurface.h"
#include "tessera/subdiv/TriangleCage.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace tessera::creature {

namespace {

/// The sub-face tile size whose coefficients per area match `texelsPerArea`
/// over the cage's mean sub-face (a triangle's third), rounded in log2.
uint32_t matchingLog2Size(const subdiv::ObjShape& shape, double texelsPerArea) {
    double area = 0.0;
    for (uint32_t f = 0; f < shape.faceCount(); ++f) {
        const glm::dvec3 a(shape.positions[shape.faceVertices[3 * f]]);
        const glm::dvec3 b(shape.positions[shape.faceVertices[3 * f + 1]]);
        const glm::dvec3 c(shape.positions[shape.faceVertices[3 * f + 2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    const double perSubFace = texelsPerArea * area / (3.0 * shape.faceCount());
    const double k = std::round(0.5 * std::log2(std::max(perSubFace, 1.0)));
    return uint32_t(std::clamp(k, 1.0, 8.0));
}

} // namespace

Result<SubdivBakeResult> bakeSubdivDisplacement(const character::CharacterAsset& asset, const SculptMesh& sculpt,
                                                const SubdivBakeOptions& options, const std::string& name) {
    if (sculpt.triangleCount() == 0) return fail(name, ": the sculpt is empty");
    if (!(options.searchDistance > 0.0f) || !std::isfinite(options.searchDistance))
        return fail(name, ": the search distance must be positive");
    if (options.texelsPerArea == 0.0 && (options.log2Size < 1 || options.log2Size > 8))
        return fail(name, ": tile log2 size ", std::to_string(options.log2Size), " (1 to 8)");
    if (options.measureGrid == 0) return fail(name, ": the error grid needs at least one sample a side");

    std::vector<glm::vec3> positions(asset.cage.vertices.size());
    for (size_t v = 0; v < positions.size(); ++v) positions[v] = asset.cage.vertices[v].position;
    Result<subdiv::WeldedCage> welded = subdiv::weldTriangleCage(positions, asset.cage.indices, name);
    if (!welded) return welded.error();
    const subdiv::ObjShape& shape = welded->shape;
    Result<subdiv::SubdivSurface> surface = subdiv::SubdivSurface::create(shape);
    if (!surface) return surface.error();
    Result<subdiv::PtexTopology> topology = subdiv::PtexTopology::create(shape);
    if (!topology) return topology.error();

    SubdivBakeResult result;
    SubdivBakeStats& stats = result.stats;
    stats.tileLog2Size =
        options.texelsPerArea > 0.0 ? matchingLog2Size(shape, options.texelsPerArea) : options.log2Size;
    // uniformLog2Sizes takes the quad size: sub-faces get one less, the
    // same texel size along base edges.
    std::vector<uint8_t> sizes = subdiv::DisplacementTiles::uniformLog2Sizes(*topology, stats.tileLog2Size + 1);
    const uint32_t tileCount = topology->tileCount();
    Result<subdiv::DisplacementTiles> tiles =
        subdiv::DisplacementTiles::create(std::move(topology).value(), std::move(sizes));
    if (!tiles) return fail(name, ": ", tiles.error().message);

    const Bvh bvh(sculpt.positions, sculpt.indices);
    const SubdivSampleTable table(*surface, *tiles, bvh, options.searchDistance, options.threads);
    const subdiv::ConversionReport report = subdiv::convertDisplacement(
        *tiles, [&table](uint32_t face, glm::dvec2 uv) { return table.sample(face, uv); });

    // What the file holds is what the renderer gets: measure the 16-bit
    // coefficients, not the float solve.
    std::vector<uint8_t> log2Sizes(tileCount);
    for (uint32_t t = 0; t < tileCount; ++t) log2Sizes[t] = uint8_t(tiles->log2Size(t));
    result.file = subdiv::quantizeCageTiles(log2Sizes, tiles->allCoefficients());
    result.file.cageVertices = uint32_t(asset.cage.vertices.size());
    result.file.cageTriangles = asset.cage.triangleCount();
    result.file.controlVertices = uint32_t(shape.positions.size());
    result.file.topologyHash = welded->topologyHash;
    tiles->assign(result.file.coefficients());

    stats.controlVertices = result.file.controlVertices;
    stats.ptexFaces = surface->ptexFaceCount();
    stats.patches = uint32_t(surface->patches().size());
    stats.coefficients = tiles->allCoefficients().size();
    stats.misses = table.misses();
    stats.missesFromNeighbours = table.fromNeighbours();
    stats.missesZero = table.zero();
    stats.conversionRounds = report.rounds;
    stats.converged = report.converged;
    stats.subdiv = measureSubdivError(*surface, &*tiles, bvh, options.searchDistance, options.measureGrid, options.threads);
    stats.subdivBase = measureSubdivError(*surface, nullptr, bvh, options.searchDistance, options.measureGrid, options.threads);
    if (asset.displacement) {
        // A triangle is three ptex faces: the same sample density per area.
        const uint32_t grid = uint32_t(std::lround(options.measureGrid * std::sqrt(3.0)));
        stats.planar = measurePlanarError(asset.cage, *asset.displacement, bvh, options.searchDistance, grid, options.threads);
    }
    stats.fileBytes = subdiv::encodeCageTiles(result.file).size();
    return result;
}

} // namespace tessera::creature
