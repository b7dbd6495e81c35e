#pragma once
/// @file DrawnSurface.h
/// The terrain's surface as a backend draws it in one frame: the tessellated
/// triangles, not the height field. Where a patch is drawn at a low level,
/// its flat triangles cut across the height field's hollows and bumps (a
/// 256 m patch at level 15 has 17 m segments; a hollow under one lies metres
/// below the drawn ground), so what stands on the terrain must stand on this
/// surface to be seen standing on it (docs/CROWD.md, 6.8).
///
/// Every backend draws the same surface for the same levels: the factor
/// passes share the metric (TessFactors.h; computeTessLevels is their CPU
/// reference), the patterns are Tessellator's bit for bit (the hardware's on
/// hulldomain, the pattern libraries on r2vb, streamout and meshshader), and
/// a vertex is the height field at its domain point. So the host evaluates
/// it here, with no GPU: the triangle holding (x, z) from the patch's
/// pattern (PatternLocator), and the linear interpolation of its corners'
/// heights. A patch's pattern and its points' heights are built on first use
/// and kept while its levels and the terrain (Terrain::revision) stay.

#include "tessera/terrain/TessLevels.h"
#include "tessera/terrain/TessellationSettings.h"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace tessera::tessellator {
class PatternLocator;
}

namespace tessera::terrain {

class Terrain;

class DrawnSurface {
public:
    /// Keeps a reference to `terrain`, which must outlive it. Until update()
    /// the surface is the untessellated control mesh (every level 1).
    explicit DrawnSurface(const Terrain& terrain);
    ~DrawnSurface();
    DrawnSurface(const DrawnSurface&) = delete;
    DrawnSurface& operator=(const DrawnSurface&) = delete;

    /// This frame's surface: the levels a backend whose highest level is
    /// `backendMaxLevel` draws with `settings` seen from `view`
    /// (computeTessLevels; LowRes is every level 1). A patch whose levels
    /// changed forgets its pattern; a splat since the last update, every
    /// patch its heights. Not concurrent with heightAt().
    void update(const TessellationSettings& settings, const TessView& view, float backendMaxLevel);
    /// No terrain is drawn this frame (it is hidden): until the next
    /// update(), heightAt() is the height field's, Terrain::heightAt, as
    /// anything standing on it was placed before there was a drawn surface.
    void useHeightField() { mHeightField = true; }

    /// The drawn surface's height (metres) at world (x, z), clamped to the
    /// control mesh. Thread-safe: concurrent calls build a patch's pattern
    /// once. The corners' heights are Terrain::heightAt as it was at the
    /// first query after update().
    float heightAt(float x, float z) const;

    const TessLevels& levels() const { return mLevels; }
    /// The quad factors of `patch` as the backends set them: outer levels in
    /// Vulkan order, then the inner levels (innerLevels()).
    std::array<float, 6> patchFactors(uint32_t patch) const;

private:
    struct Patch {
        std::array<float, 6> factors{};
        std::unique_ptr<std::once_flag> built;
        std::unique_ptr<tessellator::PatternLocator> locator;
        std::vector<float> heights; ///< per pattern point, the height field there
    };

    /// Patch `index`, its pattern and heights built.
    const Patch& built(uint32_t index) const;

    const Terrain& mTerrain;
    TessLevels mLevels;
    uint64_t mRevision = 0;    ///< the terrain's, at the last update
    bool mHeightField = false; ///< useHeightField() since the last update
    mutable std::vector<Patch> mPatches;
};

} // namespace tessera::terrain
