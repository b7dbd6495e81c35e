#include "tessera/runtime/SubdivModels.h"

#include "subdiv/SubdivPlanning.h"

#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/subdiv/DisplacementConversion.h"
#include "tessera/subdiv/ProceduralDisplacement.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace tessera::runtime {

namespace {

/// Tiles of 16 x 16 coefficients per quad (sub-faces of n-gons 8 x 8, the
/// same texel size along base edges), as the paper's examples and
/// DeformationGPU use.
constexpr uint32_t kQuadTileLog2 = 4;
/// The height a surface stands at, whatever units its file uses.
constexpr float kStandingHeight = 1.6f;

} // namespace

Result<SubdivModels::Surface> SubdivModels::build(const std::string& file, const SubdivOptions& options) {
    TESSERA_CPU_SCOPE("load.subdivSurface");
    Surface s;
    s.file = file;
    Result<subdiv::ObjShape> shape = subdiv::readObjShape(file);
    if (!shape) return shape.error();
    s.shape = std::move(shape).value();
    Result<subdiv::SubdivSurface> surface = subdiv::SubdivSurface::create(s.shape);
    if (!surface) return surface.error();
    s.surface = std::make_unique<subdiv::SubdivSurface>(std::move(surface).value());
    Result<subdiv::SubdivGpuMesh> mesh = subdiv::SubdivGpuMesh::build(s.shape, *s.surface);
    if (!mesh) return mesh.error();
    s.mesh = std::move(mesh).value();

    // Sculpting needs tiles even over the bare base surface.
    if (options.amplitude > 0.0f || options.sculpt != 0) {
        Result<subdiv::PtexTopology> topology = subdiv::PtexTopology::create(s.shape);
        if (!topology) return topology.error();
        std::vector<uint8_t> sizes = subdiv::DisplacementTiles::uniformLog2Sizes(topology.value(), kQuadTileLog2);
        Result<subdiv::DisplacementTiles> tiles =
            subdiv::DisplacementTiles::create(std::move(topology).value(), std::move(sizes));
        if (!tiles) return fail(file, ": ", tiles.error().message);
        subdiv::ProceduralDisplacement::Settings settings;
        settings.amplitude = options.amplitude;
        const subdiv::ProceduralDisplacement procedural(*s.surface, settings);
        subdiv::convertDisplacement(tiles.value(), procedural.sampler());
        s.tiles = std::move(tiles).value();
        for (const shader::TileRecord& r : s.tiles->tileRecords()) s.records.push_back(r.data);
        for (float t : s.tiles->texels()) s.maxDisplacement = std::max(s.maxDisplacement, std::abs(t));
        if (options.sculpt != 0) s.brush.emplace(*s.surface, *s.tiles);
    }

    // The limit surface's own box (sampled; the cage's is larger), grown by
    // the displacement, sets the size and where the surface stands.
    scene::Aabb box = scene::Aabb::empty();
    for (uint32_t f = 0; f < s.surface->ptexFaceCount(); ++f)
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
                if (auto p = s.surface->evaluatePtex(f, glm::dvec2(i / 8.0, j / 8.0))) box.expand(glm::vec3(p->position));
    if (box.isEmpty()) return fail(file, ": no face has a limit surface (every face is a hole)");
    box.min -= glm::vec3(s.maxDisplacement);
    box.max += glm::vec3(s.maxDisplacement);
    s.box = box;
    const glm::vec3 extent = box.max - box.min;
    const float largest = std::max({extent.x, extent.y, extent.z, 1e-6f});
    const float scale = kStandingHeight / largest;
    // Centred on the origin in x and z, standing on y = 0.
    const glm::vec3 centre = box.center();
    s.model = glm::scale(glm::mat4(1.0f), glm::vec3(scale)) *
              glm::translate(glm::mat4(1.0f), glm::vec3(-centre.x, -box.min.y, -centre.z));
    s.pivot = glm::vec3(centre.x, box.min.y, centre.z);
    s.height = std::max(extent.y, 1e-6f);
    s.pose = s.shape.positions;
    s.posed = s.pose;
    s.cage.resize(s.pose.size());
    return s;
}

Result<std::unique_ptr<SubdivModels>> SubdivModels::load(const Options& options, const terrain::Terrain& terrain,
                                                         glm::vec2 site) {
    std::unique_ptr<SubdivModels> models(new SubdivModels());
    models->mOptions = options.subdiv;
    for (const std::string& file : options.surfaces) {
        Result<Surface> built = build(file, options.subdiv);
        if (!built) return built.error();
        models->mSurfaces.push_back(std::move(built).value());
    }
    // A row across the site, 2 m apart, each on the ground below it.
    const float spacing = 2.2f;
    const size_t n = models->mSurfaces.size();
    models->mBounds = scene::Aabb::empty();
    for (size_t i = 0; i < n; ++i) {
        Surface& s = models->mSurfaces[i];
        const glm::vec2 at = site + glm::vec2(spacing * (float(i) - 0.5f * float(n - 1)), 0.0f);
        // Above the highest ground under its footprint (a flat shape lying
        // down would sink into a slope otherwise).
        const glm::vec3 lo(s.model * glm::vec4(s.box.min, 1.0f)), hi(s.model * glm::vec4(s.box.max, 1.0f));
        float ground = -1e30f;
        for (int a = 0; a <= 8; ++a)
            for (int b = 0; b <= 8; ++b)
                ground = std::max(ground, terrain.heightAt(at.x + glm::mix(lo.x, hi.x, a / 8.0f),
                                                           at.y + glm::mix(lo.z, hi.z, b / 8.0f)));
        const glm::mat4 place = glm::translate(glm::mat4(1.0f), glm::vec3(at.x, ground + 0.02f, at.y));
        s.model = place * s.model;
        models->mBounds.expand(s.box.transformed(s.model));
    }
    return models;
}

backend::SubdivDesc SubdivModels::desc(size_t i) const {
    const Surface& s = mSurfaces[i];
    backend::SubdivDesc desc;
    desc.mesh = &s.mesh;
    if (s.tiles) desc.tiles = subdivTileData(*s.tiles, s.records);
    return desc;
}

std::pair<uint64_t, uint64_t> SubdivModels::tileFigures() const {
    uint64_t samples = 0, bytes = 0;
    for (const Surface& s : mSurfaces) {
        if (!s.tiles) continue;
        samples += s.tiles->allCoefficients().size();
        bytes += s.tiles->texels().size() * sizeof(float) + s.records.size() * sizeof(glm::uvec4);
    }
    return {samples, bytes};
}

uint32_t SubdivModels::domainCount() const {
    uint32_t domains = 0;
    for (const Surface& s : mSurfaces) domains += s.mesh.domainCount();
    return domains;
}

void SubdivModels::animate(Surface& s, double seconds) const {
    // A sway about the vertical axis through the base, growing with height:
    // every control point moves, so the GPU refines a new surface each frame.
    const float sway = mOptions.animate ? 0.18f * float(std::sin(0.9 * seconds)) : 0.0f;
    for (size_t v = 0; v < s.pose.size(); ++v) {
        const glm::vec3 p = s.pose[v] - s.pivot;
        const float angle = sway * std::clamp(p.y / s.height, 0.0f, 1.0f);
        const float c = std::cos(angle), sn = std::sin(angle);
        s.posed[v] = s.pivot + glm::vec3(c * p.x + sn * p.z, p.y, -sn * p.x + c * p.z);
        s.cage[v] = glm::vec4(s.posed[v], 1.0f);
    }
}

std::vector<glm::uvec4> SubdivModels::sculpt(Surface& s) {
    if (!s.brush || !s.tiles) return {};
    TESSERA_CPU_SCOPE("subdiv.sculpt");
    // The stroke circles the surface at mid-height, waving up and down, in
    // steps shorter than the dab's radius so the dabs merge into a ridge
    // (raise) or a groove (lower).
    const glm::vec3 extent = s.box.max - s.box.min;
    const float size = std::max({extent.x, extent.y, extent.z});
    const float angle = 0.12f * float(mDabs);
    const glm::vec3 target = s.box.center() + glm::vec3(0.75f * size * std::cos(angle),
                                                        0.15f * extent.y * std::sin(3.0f * angle),
                                                        0.75f * size * std::sin(angle));
    subdiv::SculptDab dab;
    dab.centre = s.brush->nearestSurfacePoint(target);
    dab.radius = 0.12f * size;
    dab.amount = float(mOptions.sculpt) * 0.015f * size;
    const subdiv::TileUpdate update = s.brush->apply(*s.tiles, dab);
    // Culling grows with what the brush may have added.
    s.maxDisplacement += std::abs(dab.amount);
    return subdiv::SculptBrush::uploadRects(*s.tiles, update);
}

void SubdivModels::update(double seconds, const scene::Camera& camera, uint32_t viewportHeight, float levelCap,
                          uint64_t budget) {
    TESSERA_CPU_SCOPE("subdiv.lod");
    const subdiv::SubdivView view = subdivView(camera, viewportHeight);
    float level = mOptions.level.value_or(0.0f);
    if (mOptions.level && mLevelEnd && mSweepSeconds > 0.0)
        level += (*mLevelEnd - level) * float(std::clamp(seconds / mSweepSeconds, 0.0, 1.0));
    subdiv::SubdivLodSettings settings = subdivSettings(mOptions, levelCap, level);

    std::vector<std::vector<glm::uvec4>> rewritten;
    for (Surface& s : mSurfaces) {
        animate(s, seconds);
        rewritten.push_back(sculpt(s));
    }
    const std::vector<subdiv::SubdivLodFrame> frames =
        planWithinBudget(mSurfaces.size(), budget, [&](size_t i, uint64_t share) {
            const Surface& s = mSurfaces[i];
            settings.displacementScale = s.tiles ? 1.0f : 0.0f;
            settings.maxDisplacement = s.maxDisplacement;
            settings.triangleBudget = share;
            return subdiv::SubdivLod::plan(s.mesh, s.posed, s.model, view, settings);
        });
    mDraws.clear();
    mPredicted = 0;
    for (size_t i = 0; i < mSurfaces.size(); ++i) {
        Surface& s = mSurfaces[i];
        SubdivDraw draw{s.handle, {frames[i].uniforms, s.cage}, {}, std::move(rewritten[i])};
        if (!draw.tileRects.empty()) draw.tiles = desc(i).tiles;
        mDraws.push_back(std::move(draw));
        mPredicted += frames[i].prediction.triangles;
    }
    if (mOptions.sculpt != 0) ++mDabs;
}

} // namespace tessera::runtime
