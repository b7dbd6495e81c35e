#pragma once
/// @file SubdivModels.h
/// The characters scene's Catmull-Clark surfaces (--model FILE.obj, the
/// second paper): each control mesh read with its OpenSubdiv tags, built
/// into patches, given a procedural displacement in the paper's tile
/// format, scaled to stand about 1.6 m tall on the terrain, its cage swaying
/// gently; per frame the level of detail (subdiv::SubdivLod) within the
/// frame's triangle budget and the backend's level cap.

#include "tessera/runtime/Options.h"
#include "tessera/runtime/SubdivSource.h"
#include "tessera/backend/SubdivDesc.h"
#include "tessera/core/Result.h"
#include "tessera/scene/Aabb.h"
#include "tessera/scene/Camera.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/ObjShape.h"
#include "tessera/subdiv/SculptBrush.h"
#include "tessera/subdiv/SubdivGpuMesh.h"
#include "tessera/subdiv/SubdivLod.h"
#include "tessera/subdiv/SubdivSurface.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tessera::runtime {

/// One surface's draw this frame.
struct SubdivDraw {
    backend::SubdivHandle handle;
    backend::SubdivDrawInfo info;
    /// Tiles a sculpt dab rewrote this frame: re-upload these texel
    /// rectangles of `tiles` before the draw (empty: nothing changed).
    backend::SubdivTileData tiles;
    std::vector<glm::uvec4> tileRects;
};

class SubdivModels final : public SubdivSource {
public:
    /// Reads and builds every file; stands them in a row centred on `site`
    /// (x, z; the terrain's height below). Errors name the file.
    static Result<std::unique_ptr<SubdivModels>> load(const Options& options, const terrain::Terrain& terrain,
                                                      glm::vec2 site);

    /// The row's world box (for framing the camera).
    const scene::Aabb& bounds() const { return mBounds; }
    size_t size() const override { return mSurfaces.size(); }

    /// What createSubdiv needs for surface `i` (valid while this lives).
    backend::SubdivDesc desc(size_t i) const override;
    void setHandle(size_t i, backend::SubdivHandle handle) override { mSurfaces[i].handle = handle; }

    /// Animates the cages to `seconds` and plans each surface's level of
    /// detail for `camera` on a `viewportHeight`-pixel target, with the
    /// backend's `levelCap` and the frame's `budget` (triangles) shared by
    /// all surfaces in proportion to what each would take.
    void update(double seconds, const scene::Camera& camera, uint32_t viewportHeight, float levelCap,
                uint64_t budget);
    std::span<const SubdivDraw> draws() const { return mDraws; }
    /// --subdiv-level A:B: the fixed level goes from A to B over `seconds`.
    void sweepLevel(float end, double seconds) {
        mLevelEnd = end;
        mSweepSeconds = seconds;
    }
    /// Every surface's displacement: tile samples (coefficients), and the
    /// bytes of the packed texture and records.
    std::pair<uint64_t, uint64_t> tileFigures() const;
    /// Domains of every surface.
    uint32_t domainCount() const;
    /// Triangles the CPU reference predicts for this frame's draws.
    uint64_t predictedTriangles() const { return mPredicted; }

private:
    struct Surface {
        std::string file;
        subdiv::ObjShape shape;
        std::unique_ptr<subdiv::SubdivSurface> surface;
        subdiv::SubdivGpuMesh mesh;
        std::optional<subdiv::DisplacementTiles> tiles;
        std::vector<glm::uvec4> records;
        float maxDisplacement = 0.0f;
        glm::mat4 model{1.0f};
        scene::Aabb box;       ///< object-space box of the displaced limit surface
        glm::vec3 pivot{0.0f}; ///< object-space centre of the sway
        float height = 1.0f;   ///< object-space height of the cage
        backend::SubdivHandle handle;
        std::vector<glm::vec3> pose;  ///< the rest pose
        std::vector<glm::vec3> posed; ///< this frame's control points
        std::vector<glm::vec4> cage;  ///< the same, as the backend takes them
        std::optional<subdiv::SculptBrush> brush; ///< --sculpt
    };

    SubdivModels() = default;
    static Result<Surface> build(const std::string& file, const SubdivOptions& options);
    void animate(Surface& s, double seconds) const;
    /// --sculpt: this frame's dab on `s`; the texel rectangles to re-upload.
    std::vector<glm::uvec4> sculpt(Surface& s);

    SubdivOptions mOptions;
    std::vector<Surface> mSurfaces;
    std::vector<SubdivDraw> mDraws;
    scene::Aabb mBounds;
    uint64_t mPredicted = 0;
    std::optional<float> mLevelEnd;
    double mSweepSeconds = 0.0;
    uint32_t mDabs = 0;
};

} // namespace tessera::runtime
