#pragma once
/// @file TemplateBackend.h
/// The smallest complete backend: every command of the contract, each doing
/// nothing, with no GPU needed. Copy this folder to start a new backend (see
/// README.md). The test plugins derive from it to break one rule each
/// (tests/plugins).

#include "tessera/backend/PluginApi.h"

namespace tessera::plugins {

class TemplateBackend : public backend::Backend {
public:
    backend::BackendCapabilities capabilities(const device::DeviceFeatures*) override {
        backend::BackendCapabilities caps;
        caps.name = "template";
        caps.description = "template for new backends (draws nothing)";
        caps.requiresGpu = false;
        return caps;
    }
    Status initialize(const backend::BackendInitInfo&) override { return {}; }
    void shutdown() override {}
    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc&) override {
        return backend::TerrainHandle{0};
    }
    void destroyTerrain(backend::TerrainHandle) override {}
    void beginFrame(const backend::FrameInfo& frame) override {
        mReport = {};
        mReport.frameIndex = frame.frameIndex;
    }
    void splatTerrain(backend::TerrainHandle, std::span<const terrain::CraterSplat>) override {}
    void drawTerrain(backend::TerrainHandle, const backend::TerrainDrawInfo&) override {}
    Result<std::vector<uint16_t>> readTerrainHeights(backend::TerrainHandle) override {
        return fail("this backend keeps no GPU copy of the terrain");
    }
    Result<backend::CharacterHandle> createCharacter(const backend::CharacterDesc&) override {
        return backend::CharacterHandle{0};
    }
    void destroyCharacter(backend::CharacterHandle) override {}
    void drawCharacters(const backend::CharacterDrawInfo&) override {}
    Result<backend::CrowdHandle> createCrowd(const backend::CrowdDesc&) override {
        return fail("this backend draws no instanced crowds");
    }
    void destroyCrowd(backend::CrowdHandle) override {}
    void drawCrowd(backend::CrowdHandle, const backend::CrowdDrawInfo&) override {}
    Result<backend::CrowdTiers> readCrowdTiers(backend::CrowdHandle) override {
        return fail("this backend draws no instanced crowds");
    }
    Result<backend::SubdivHandle> createSubdiv(const backend::SubdivDesc&) override {
        return fail("this backend draws no subdivision surfaces");
    }
    void destroySubdiv(backend::SubdivHandle) override {}
    void updateSubdivTiles(backend::SubdivHandle, const backend::SubdivTileData&, std::span<const glm::uvec4>) override {}
    void drawSubdiv(backend::SubdivHandle, const backend::SubdivDrawInfo&) override {}
    Result<backend::SubdivPoints> readSubdivPoints(backend::SubdivHandle) override {
        return fail("this backend draws no subdivision surfaces");
    }
    void endFrame() override {}
    backend::FrameReport lastFrameReport() override { return mReport; }

private:
    backend::FrameReport mReport;
};

} // namespace tessera::plugins
