#include "tessera/subdiv/CageTiles.h"

#include "tessera/subdiv/TriangleCage.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tessera::subdiv {

uint64_t CageTiles::coefficientCount() const {
    uint64_t n = 0;
    for (uint8_t k : log2Sizes) n += uint64_t(1) << (2u * k);
    return n;
}

std::vector<float> CageTiles::coefficients() const {
    std::vector<float> out(quantized.size());
    // In double, so the same bytes give the same floats however the
    // compiler contracts float arithmetic.
    for (size_t i = 0; i < quantized.size(); ++i)
        out[i] = float(double(quantized[i]) / 65535.0 * double(scale) + double(bias));
    return out;
}

CageTiles quantizeCageTiles(std::span<const uint8_t> log2Sizes, std::span<const float> coefficients) {
    CageTiles tiles;
    tiles.log2Sizes.assign(log2Sizes.begin(), log2Sizes.end());
    float lo = 0.0f, hi = 0.0f;
    if (!coefficients.empty()) {
        auto [mn, mx] = std::minmax_element(coefficients.begin(), coefficients.end());
        lo = *mn;
        hi = *mx;
    }
    tiles.bias = lo;
    tiles.scale = hi - lo;
    tiles.quantized.resize(coefficients.size());
    for (size_t i = 0; i < coefficients.size(); ++i) {
        const double q = tiles.scale > 0.0f ? (double(coefficients[i]) - lo) / double(tiles.scale) * 65535.0 : 0.0;
        tiles.quantized[i] = uint16_t(std::clamp(std::lround(q), 0l, 65535l));
    }
    return tiles;
}

Status checkCageTiles(const CageTiles& tiles, const WeldedCage& cage, uint32_t cageVertices, uint32_t tileCount,
                      const std::string& name) {
    auto mismatch = [&](const char* what, uint64_t file, uint64_t glb) {
        return fail(name, ": baked for another cage: ", what, " ", std::to_string(file), " in the file, ",
                    std::to_string(glb), " in the model (regenerate the .cctiles beside the .glb)");
    };
    if (tiles.cageVertices != cageVertices) return mismatch("cage vertices", tiles.cageVertices, cageVertices);
    const uint32_t triangles = cage.shape.faceCount();
    if (tiles.cageTriangles != triangles) return mismatch("cage triangles", tiles.cageTriangles, triangles);
    const uint32_t control = uint32_t(cage.shape.positions.size());
    if (tiles.controlVertices != control) return mismatch("control vertices", tiles.controlVertices, control);
    if (tiles.topologyHash != cage.topologyHash) return mismatch("topology hash", tiles.topologyHash, cage.topologyHash);
    if (tiles.log2Sizes.size() != tileCount) return mismatch("tiles", tiles.log2Sizes.size(), tileCount);
    return {};
}

} // namespace tessera::subdiv
