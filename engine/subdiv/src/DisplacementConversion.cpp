#include "tessera/subdiv/DisplacementConversion.h"

#include "TileInterpolator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace tessera::subdiv {

namespace {

glm::uvec2 cornerTexel(uint32_t corner, uint32_t n) {
    return {corner == 1 || corner == 2 ? n : 1u, corner >= 2 ? n : 1u};
}

bool extraordinary(const PtexTopology& topology, uint32_t tile, uint32_t corner) {
    return topology.fan(topology.tile(tile).fans[corner]).kind == FanKind::Extraordinary;
}

} // namespace

ConversionReport convertDisplacement(DisplacementTiles& tiles, const DisplacementSampler& sample,
                                     const ConversionOptions& options) {
    const PtexTopology& topology = tiles.topology();
    ConversionReport report;
    std::vector<double> samples(tiles.allCoefficients().size());
    for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
        const uint32_t n = tiles.tileSize(t);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const double s = sample(t, (glm::dvec2(x, y) + 0.5) / double(n));
                samples[tiles.firstCoefficient(t) + size_t(y) * n + x] = s;
                report.sampleScale = std::max(report.sampleScale, std::abs(s));
            }
    }
    // Extraordinary corners start at the mean of the samples at the vertex
    // (each tile samples its own corner; the limit positions agree to
    // round-off, so these are one value up to it).
    std::vector<float> coefficients(samples.begin(), samples.end());
    for (uint32_t f = 0; f < topology.fanCount(); ++f) {
        if (topology.fan(f).kind != FanKind::Extraordinary) continue;
        double sum = 0.0;
        for (const TileCorner& c : topology.fanCorners(f)) sum += sample(c.tile, PtexTopology::cornerUV(c.corner));
        const float mean = float(sum / topology.fan(f).cornerCount);
        for (const TileCorner& c : topology.fanCorners(f)) {
            const uint32_t n = tiles.tileSize(c.tile);
            const glm::uvec2 p = cornerTexel(c.corner, n) - 1u;
            coefficients[tiles.firstCoefficient(c.tile) + size_t(p.y) * n + p.x] = mean;
        }
    }
    tiles.assign(coefficients);

    std::array<std::unique_ptr<detail::TileInterpolator>, TS_TILE_MAX_LOG2_SIZE + 1> solvers;
    const double limit = options.tolerance * std::max(report.sampleScale, 1e-30);
    std::vector<double> grid;
    for (uint32_t round = 1; round <= options.maxRounds && !report.converged; ++round) {
        // Every tile from the previous round's texture (its overlaps and
        // corner averages), then one rederivation.
        double change = 0.0;
        for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
            const uint32_t k = tiles.log2Size(t), n = 1u << k, side = n + 2;
            if (!solvers[k]) solvers[k] = std::make_unique<detail::TileInterpolator>(n);
            grid.resize(size_t(side) * side);
            for (uint32_t y = 0; y < side; ++y)
                for (uint32_t x = 0; x < side; ++x) grid[size_t(y) * side + x] = tiles.texel(t, 0, x, y);
            std::vector<detail::PinnedCoefficient> pins;
            for (uint32_t c = 0; c < 4; ++c)
                if (extraordinary(topology, t, c)) {
                    const glm::uvec2 p = cornerTexel(c, n);
                    pins.push_back({p, grid[size_t(p.y) * side + p.x]});
                }
            // A boundary side is extrapolated from the tile itself: solved
            // as such (exactly, not from the last round), unless an
            // extraordinary corner's block sits on it.
            std::array<bool, 4> extrapolated{};
            const PtexTile& tile = topology.tile(t);
            for (uint32_t e = 0; e < 4; ++e)
                extrapolated[e] = tile.edges[e].count == 0 && !extraordinary(topology, t, e) &&
                                  !extraordinary(topology, t, (e + 1) % 4);
            const size_t first = tiles.firstCoefficient(t);
            solvers[k]->solve(grid, std::span<const double>(samples).subspan(first, size_t(n) * n), pins, extrapolated);
            for (uint32_t y = 0; y < n; ++y)
                for (uint32_t x = 0; x < n; ++x) {
                    float& c = coefficients[first + size_t(y) * n + x];
                    const float solved = float(grid[size_t(y + 1) * side + x + 1]);
                    change = std::max(change, double(std::abs(solved - c)));
                    c = solved;
                }
        }
        tiles.assign(coefficients);
        report.rounds = round;
        report.converged = change <= limit;
    }

    for (uint32_t t = 0; t < tiles.tileCount(); ++t) {
        const uint32_t n = tiles.tileSize(t);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / float(n);
                const double d = tiles.evaluateLevel(t, 0, uv).value.x;
                const double residual = std::abs(d - samples[tiles.firstCoefficient(t) + size_t(y) * n + x]);
                bool pinned = false;
                for (uint32_t c = 0; c < 4; ++c)
                    pinned = pinned || (extraordinary(topology, t, c) && cornerTexel(c, n) == glm::uvec2(x, y) + 1u);
                if (pinned) {
                    ++report.pinnedSamples;
                    report.maxPinnedResidual = std::max(report.maxPinnedResidual, residual);
                } else {
                    ++report.samples;
                    report.maxResidual = std::max(report.maxResidual, residual);
                }
            }
    }
    return report;
}

} // namespace tessera::subdiv
