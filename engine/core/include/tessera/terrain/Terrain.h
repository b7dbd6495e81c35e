#pragma once
/// @file Terrain.h
/// The terrain as gameplay and renderers see it: the CPU height field, its
/// control mesh, bounds pyramid and detail, culling, and deformation.

#include "tessera/scene/Frustum.h"
#include "tessera/terrain/CraterSplat.h"
#include "tessera/terrain/HeightField.h"
#include "tessera/terrain/MinMaxPyramid.h"
#include "tessera/terrain/PatchGrid.h"
#include "tessera/terrain/TerrainDetail.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace tessera::terrain {

/// Owns the CPU copy of the height field and everything derived from it.
/// Every deformation goes through splat(), which updates the samples, the
/// bounds pyramid and the detail errors at once and queues the splat for the
/// renderer, so gameplay queries, culling, tessellation and the GPU copy agree
/// in the same frame. Not copyable (the derived data refers to the field).
class Terrain {
public:
    /// Default control mesh: 64 x 64 patches (about 128 m each on the 8 km content map).
    static constexpr uint32_t kDefaultPatchesPerSide = 32;

    explicit Terrain(HeightField field, uint32_t patchesPerSide = kDefaultPatchesPerSide);
    Terrain(const Terrain&) = delete;
    Terrain& operator=(const Terrain&) = delete;

    const HeightField& field() const { return *mField; }
    const PatchGrid& grid() const { return *mGrid; }
    const MinMaxPyramid& bounds() const { return *mBounds; }
    const TerrainDetail& detail() const { return *mDetail; }

    /// Ground height (metres) and unit normal at world (x, z); see HeightField.
    float heightAt(float x, float z) const { return mField->heightAt(x, z); }
    glm::vec3 normalAt(float x, float z) const { return mField->normalAt(x, z); }

    /// Appends the patches whose displaced bounds intersect `frustum`, walking
    /// the min/max pyramid from the top (whole blocks inside the frustum are
    /// taken without further tests), nearer blocks first so early depth
    /// testing rejects hidden fragments.
    void cull(const scene::Frustum& frustum, const glm::vec3& eye, std::vector<uint32_t>& visible) const;

    /// Stamps a crater into the CPU copy, updates bounds and detail around it
    /// and queues it for the GPU copy. Returns the samples that may have changed.
    SampleRect splat(const CraterSplat& splat);
    /// The same, from its parts: a crater of `radius` metres at world (x, z) = `center`.
    SampleRect splat(glm::vec2 center, float radius, const CraterProfile& profile = {}) {
        return splat(CraterSplat{center, radius, profile});
    }

    /// Splats made since the last call, in order, for the renderer to apply
    /// to its GPU copy; clears the queue.
    std::vector<CraterSplat> takePendingSplats();

    /// Increases with every splat; renderers re-upload derived data (detail
    /// errors) when it changes.
    uint64_t revision() const { return mRevision; }

    /// Every splat since construction, in order (revision() of them), for
    /// systems that react to deformation on their own schedule (the crowd
    /// reads the ones it has not seen at its next step).
    std::span<const CraterSplat> splatHistory() const { return mHistory; }

private:
    void cullCell(const scene::Frustum& frustum, const glm::vec3& eye, uint32_t level, uint32_t x, uint32_t z,
                  bool inside, std::vector<uint32_t>& visible) const;
    void appendAll(uint32_t level, uint32_t x, uint32_t z, std::vector<uint32_t>& visible) const;

    std::unique_ptr<HeightField> mField;
    std::unique_ptr<PatchGrid> mGrid;
    std::unique_ptr<MinMaxPyramid> mBounds;
    std::unique_ptr<TerrainDetail> mDetail;
    std::vector<CraterSplat> mHistory;
    size_t mPendingFrom = 0; ///< first splat takePendingSplats() has not handed out
    uint64_t mRevision = 0;
};

} // namespace tessera::terrain
