#pragma once
/// @file SubdivCharacters.h
/// The characters scene's --model .glb files drawn as Catmull-Clark surfaces
/// with the second paper's tile displacement (--character-surface
/// catmull-clark or both; docs/SUBDIV.md, "The Froblin as a Catmull-Clark
/// surface"): each file's cage welded into a control mesh
/// (subdiv::weldTriangleCage), its tiles read from the .cctiles file beside
/// it (subdiv::readCageTiles, checked against that cage), skinned on the CPU
/// every frame with the clip the planar character plays, and planned by
/// subdiv::SubdivLod as SubdivModels plans the .obj shapes. `catmull-clark`
/// stands each where the planar one would stand (the planar one is left
/// out); `both` stands it beside the planar one, to its right as the camera
/// starts.

#include "tessera/runtime/Options.h"
#include "tessera/runtime/SubdivModels.h"
#include "tessera/runtime/SubdivSource.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/character/Pose.h"
#include "tessera/core/Result.h"
#include "tessera/scene/Aabb.h"
#include "tessera/scene/Camera.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/SubdivGpuMesh.h"
#include "tessera/subdiv/SubdivSurface.h"
#include "tessera/subdiv/TriangleCage.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tessera::runtime {

class SubdivCharacters final : public SubdivSource {
public:
    /// The .cctiles file beside a .glb (froblin_1.glb: froblin_1.cctiles).
    static std::string tilesFileFor(const std::string& glb);

    /// Loads every --model .glb/.gltf with its .cctiles and places it on
    /// `terrain` as CharacterCrowd places the planar models around `site`
    /// (x, z). Errors name the file: a model or tile file that cannot be
    /// read, tiles baked for another cage, a cage Catmull-Clark cannot refine.
    static Result<std::unique_ptr<SubdivCharacters>> load(const Options& options, const terrain::Terrain& terrain,
                                                          glm::vec3 site);

    /// The characters' world box over their clips (for framing the camera).
    const scene::Aabb& bounds() const { return mBounds; }
    size_t size() const override { return mCharacters.size(); }
    backend::SubdivDesc desc(size_t i) const override;
    void setHandle(size_t i, backend::SubdivHandle handle) override { mCharacters[i].handle = handle; }

    /// Poses and skins the cages at `seconds` and plans the level of
    /// detail (as SubdivModels::update).
    void update(double seconds, const scene::Camera& camera, uint32_t viewportHeight, float levelCap,
                uint64_t budget);
    std::span<const SubdivDraw> draws() const { return mDraws; }
    uint64_t predictedTriangles() const { return mPredicted; }
    /// Domains of every character's surface.
    uint32_t domainCount() const;
    /// Triangles of every character's planar cage (the first paper's).
    uint64_t cageTriangles() const;

private:
    struct Character {
        std::string file;
        character::CharacterAsset asset;
        subdiv::WeldedCage cage;
        std::unique_ptr<subdiv::SubdivSurface> surface;
        subdiv::SubdivGpuMesh mesh;
        std::optional<subdiv::DisplacementTiles> tiles;
        std::vector<glm::uvec4> records;
        float maxDisplacement = 0.0f;
        glm::vec3 albedo{0.72f, 0.66f, 0.58f}; ///< the base colour texture's mean, if any
        int clip = -1;
        glm::mat4 model{1.0f};
        scene::Aabb box; ///< object space, over the clips, grown by the displacement
        backend::SubdivHandle handle;
        std::unique_ptr<character::Pose> pose;
        std::vector<glm::mat4> palette;
        std::vector<glm::vec3> skinned;
        std::vector<glm::vec4> cageFrame;
    };

    SubdivCharacters() = default;
    static Result<Character> build(const std::string& file);
    void skin(Character& c, double seconds) const;

    SubdivOptions mOptions;
    std::vector<Character> mCharacters;
    std::vector<SubdivDraw> mDraws;
    scene::Aabb mBounds;
    uint64_t mPredicted = 0;
};

} // namespace tessera::runtime
