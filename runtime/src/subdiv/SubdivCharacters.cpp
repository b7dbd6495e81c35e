#include "tessera/runtime/SubdivCharacters.h"

#include "subdiv/SubdivPlanning.h"

#include "tessera/runtime/CameraOrbit.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/character/AnimatedBounds.h"
#include "tessera/character/SkinnedVertex.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/subdiv/CageTiles.h"
#include "tessera/subdiv/PtexTopology.h"
#include "tessera/subdiv/SubdivLod.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

namespace tessera::runtime {

std::string SubdivCharacters::tilesFileFor(const std::string& glb) {
    return std::filesystem::path(glb).replace_extension(".cctiles").string();
}

Result<SubdivCharacters::Character> SubdivCharacters::build(const std::string& file) {
    TESSERA_CPU_SCOPE("load.subdivCharacter");
    Character c;
    c.file = file;
    Result<character::CharacterAsset> asset = assets::loadCharacter(file);
    if (!asset) return asset.error();
    c.asset = std::move(asset).value();
    std::vector<glm::vec3> positions(c.asset.cage.vertices.size());
    for (size_t v = 0; v < positions.size(); ++v) positions[v] = c.asset.cage.vertices[v].position;
    Result<subdiv::WeldedCage> cage = subdiv::weldTriangleCage(positions, c.asset.cage.indices, file);
    if (!cage) return cage.error();
    c.cage = std::move(cage).value();

    const std::string tilesFile = tilesFileFor(file);
    Result<subdiv::CageTiles> stored = subdiv::readCageTiles(tilesFile);
    if (!stored) return stored.error();
    Result<subdiv::PtexTopology> topology = subdiv::PtexTopology::create(c.cage.shape);
    if (!topology) return topology.error();
    if (Status ok = subdiv::checkCageTiles(*stored, c.cage, uint32_t(positions.size()), topology->tileCount(),
                                           tilesFile);
        !ok)
        return ok.error();
    Result<subdiv::DisplacementTiles> tiles =
        subdiv::DisplacementTiles::create(std::move(topology).value(), stored->log2Sizes);
    if (!tiles) return fail(tilesFile, ": ", tiles.error().message);
    tiles->assign(stored->coefficients());
    c.tiles = std::move(tiles).value();
    for (const shader::TileRecord& r : c.tiles->tileRecords()) c.records.push_back(r.data);
    for (float t : c.tiles->texels()) c.maxDisplacement = std::max(c.maxDisplacement, std::abs(t));

    Result<subdiv::SubdivSurface> surface = subdiv::SubdivSurface::create(c.cage.shape);
    if (!surface) return surface.error();
    c.surface = std::make_unique<subdiv::SubdivSurface>(std::move(surface).value());
    Result<subdiv::SubdivGpuMesh> mesh = subdiv::SubdivGpuMesh::build(c.cage.shape, *c.surface);
    if (!mesh) return mesh.error();
    c.mesh = std::move(mesh).value();

    // The box over every clip, as the planar character's, grown by the
    // largest displacement (the limit surface lies inside the cage's hull).
    c.box = character::animatedBounds(c.asset);
    // One colour for the whole surface (it has no texture coordinates of
    // its own): the mean of the base colour texture, as the character
    // shader reads its texels (no sRGB decode in either), so
    // the two versions read as the same creature side by side.
    if (c.asset.baseColor && !c.asset.baseColor->empty() && c.asset.baseColor->bytesPerTexel() == 4) {
        // Texels outside the atlas's charts (black, or transparent) are not
        // the creature's colour.
        glm::dvec3 sum(0.0);
        size_t count = 0;
        const std::vector<uint8_t>& bytes = c.asset.baseColor->bytes;
        for (size_t i = 0; i + 3 < bytes.size(); i += 4) {
            if (bytes[i + 3] == 0 || bytes[i] + bytes[i + 1] + bytes[i + 2] < 8) continue;
            for (int k = 0; k < 3; ++k) sum[k] += bytes[i + k] / 255.0;
            ++count;
        }
        if (count > 0) c.albedo = glm::vec3(sum / double(count));
    }
    c.box.min -= glm::vec3(c.maxDisplacement);
    c.box.max += glm::vec3(c.maxDisplacement);
    c.clip = c.asset.clips.empty() ? -1 : 0; // what CharacterCrowd plays for a --model
    c.skinned.resize(c.cage.shape.positions.size());
    c.cageFrame.resize(c.skinned.size());
    return c;
}

Result<std::unique_ptr<SubdivCharacters>> SubdivCharacters::load(const Options& options,
                                                                 const terrain::Terrain& terrain, glm::vec3 site) {
    std::unique_ptr<SubdivCharacters> characters(new SubdivCharacters());
    characters->mOptions = options.subdiv;
    for (const std::string& file : options.models) {
        Result<Character> built = build(file);
        if (!built) return built.error();
        characters->mCharacters.push_back(std::move(built).value());
    }
    // Where CharacterCrowd::populate stands the planar --model characters:
    // a row spaced by the largest one, centred on the site when they are
    // alone, else beside the crowd; facing where the camera starts.
    const size_t n = characters->mCharacters.size();
    float largest = 0.0f;
    for (const Character& c : characters->mCharacters) {
        const scene::Aabb box = character::animatedBounds(c.asset);
        largest = std::max(largest, glm::length(glm::vec2(box.extents().x, box.extents().z)));
    }
    const float spacing = std::max(1.5f, 2.2f * largest);
    const bool alone = options.crowd == 0;
    // `both`: to the planar one's right as the camera starts its orbit
    // (the camera sits at azimuth kStart, so its right is (cos, -sin)).
    const glm::vec2 beside = options.characterSurface == "both"
                                 ? 0.8f * spacing * glm::vec2(std::cos(CameraOrbit::kStart), -std::sin(CameraOrbit::kStart))
                                 : glm::vec2(0.0f);
    const glm::vec2 centre(site.x, site.z);
    characters->mBounds = scene::Aabb::empty();
    for (size_t k = 0; k < n; ++k) {
        Character& c = characters->mCharacters[k];
        // Made here, not in build(): a Pose points at its skeleton, which
        // must not move any more (the vector is complete).
        c.pose = std::make_unique<character::Pose>(c.asset.skeleton);
        const glm::vec2 at = beside + centre +
                             (alone ? glm::vec2(spacing * (float(k) - 0.5f * float(n - 1)), 0.0f)
                                    : glm::vec2(-spacing * float(k + 1), 0.8f));
        c.model = glm::translate(glm::mat4(1.0f), glm::vec3(at.x, terrain.heightAt(at.x, at.y), at.y));
        c.model = glm::rotate(c.model, CameraOrbit::kStart, glm::vec3(0, 1, 0));
        characters->mBounds.expand(c.box.transformed(c.model));
    }
    return characters;
}

backend::SubdivDesc SubdivCharacters::desc(size_t i) const {
    const Character& c = mCharacters[i];
    backend::SubdivDesc desc;
    desc.mesh = &c.mesh;
    desc.tiles = subdivTileData(*c.tiles, c.records);
    return desc;
}

void SubdivCharacters::skin(Character& c, double seconds) const {
    // The planar character's first pass on the CPU: the clip sampled, the
    // palette, then linear blend skinning of one cage vertex per control
    // vertex (welded copies share position and weights).
    c.pose->reset();
    if (c.clip >= 0) c.pose->apply(c.asset.clips[size_t(c.clip)], float(seconds));
    c.pose->computeGlobals();
    c.pose->palette(c.asset.cage, c.palette);
    for (size_t v = 0; v < c.skinned.size(); ++v) {
        c.skinned[v] = character::skinVertex(c.asset.cage.vertices[c.cage.firstCageVertex[v]], c.palette).position;
        c.cageFrame[v] = glm::vec4(c.skinned[v], 1.0f);
    }
}

void SubdivCharacters::update(double seconds, const scene::Camera& camera, uint32_t viewportHeight, float levelCap,
                              uint64_t budget) {
    TESSERA_CPU_SCOPE("subdiv.characters");
    const subdiv::SubdivView view = subdivView(camera, viewportHeight);
    subdiv::SubdivLodSettings settings = subdivSettings(mOptions, levelCap, mOptions.level.value_or(0.0f));
    settings.displacementScale = 1.0f;
    for (Character& c : mCharacters) skin(c, seconds);
    const std::vector<subdiv::SubdivLodFrame> frames =
        planWithinBudget(mCharacters.size(), budget, [&](size_t i, uint64_t share) {
            const Character& c = mCharacters[i];
            settings.maxDisplacement = c.maxDisplacement;
            settings.albedo = c.albedo;
            settings.triangleBudget = share;
            return subdiv::SubdivLod::plan(c.mesh, c.skinned, c.model, view, settings);
        });
    mDraws.clear();
    mPredicted = 0;
    for (size_t i = 0; i < mCharacters.size(); ++i) {
        mDraws.push_back({mCharacters[i].handle, {frames[i].uniforms, mCharacters[i].cageFrame}});
        mPredicted += frames[i].prediction.triangles;
    }
}

uint64_t SubdivCharacters::cageTriangles() const {
    uint64_t triangles = 0;
    for (const Character& c : mCharacters) triangles += c.asset.cage.indices.size() / 3;
    return triangles;
}

uint32_t SubdivCharacters::domainCount() const {
    uint32_t domains = 0;
    for (const Character& c : mCharacters) domains += c.mesh.domainCount();
    return domains;
}

} // namespace tessera::runtime
