#include "subdiv/SubdivPlanning.h"

#include <algorithm>
#include <cmath>

namespace tessera::runtime {

subdiv::SubdivView subdivView(const scene::Camera& camera, uint32_t viewportHeight) {
    subdiv::SubdivView view;
    view.frustum = camera.frustum();
    view.eye = camera.position();
    view.pixelsPerMetre = float(viewportHeight) * std::abs(camera.projection()[1][1]) * 0.5f;
    return view;
}

subdiv::SubdivLodSettings subdivSettings(const SubdivOptions& options, float levelCap, float level) {
    subdiv::SubdivLodSettings settings;
    settings.targetPixels = options.pixels.value_or(settings.targetPixels);
    settings.levelCap = levelCap;
    settings.fixedLevel = level > 0.0f ? std::min(level, levelCap) : 0.0f;
    settings.mipSelection = options.mips;
    settings.normals = options.normals;
    settings.view = options.view;
    return settings;
}

std::vector<subdiv::SubdivLodFrame>
planWithinBudget(size_t count, uint64_t budget, const std::function<subdiv::SubdivLodFrame(size_t, uint64_t)>& plan) {
    std::vector<subdiv::SubdivLodFrame> frames;
    uint64_t wanted = 0;
    for (size_t i = 0; i < count; ++i) {
        frames.push_back(plan(i, budget));
        wanted += frames.back().prediction.triangles;
    }
    if (budget > 0 && wanted > budget && count > 1)
        for (size_t i = 0; i < count; ++i)
            frames[i] = plan(i, std::max<uint64_t>(1, budget * frames[i].prediction.triangles / wanted));
    return frames;
}

backend::SubdivTileData subdivTileData(const subdiv::DisplacementTiles& tiles, std::span<const glm::uvec4> records) {
    backend::SubdivTileData data;
    data.texels = tiles.texels();
    data.width = tiles.textureWidth();
    data.height = tiles.textureHeight();
    data.records = records;
    return data;
}

} // namespace tessera::runtime
