// A GPU backend that breaks a Vulkan valid-usage rule on purpose (a viewport
// count of zero, harmless to any driver), so the tests can prove that the
// validation layer is really on and that any message fails the run.
#include "tessera/backend/PluginApi.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/RenderTarget.h"

namespace {

using namespace tessera;

class InvalidUsageBackend final : public backend::Backend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures*) override {
        backend::BackendCapabilities caps;
        caps.name = "invalid-usage";
        caps.description = "test backend that violates a Vulkan valid-usage rule";
        return caps;
    }
    Status initialize(const backend::BackendInitInfo&) override { return {}; }
    void shutdown() override {}
    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc&) override {
        return backend::TerrainHandle{0};
    }
    void destroyTerrain(backend::TerrainHandle) override {}
    void beginFrame(const backend::FrameInfo& frame) override { mFrame = frame.gpu; }
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
    void endFrame() override {
        const float clear[4] = {0, 0, 0, 1};
        mFrame->target().beginRendering(mFrame->cmd(), clear);
        VkViewport viewport{};
        vkCmdSetViewport(mFrame->cmd(), 0, 0, &viewport); // VUID-vkCmdSetViewport-viewportCount-arraylength
        mFrame->target().endRendering(mFrame->cmd());
    }
    backend::FrameReport lastFrameReport() override { return {}; }

private:
    gpu::FrameContext* mFrame = nullptr;
};

backend::Backend* create() { return new InvalidUsageBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace

TESSERA_REGISTER_PLUGIN(registry) { registry.registerBackend({"invalid-usage", &create, &destroy}); }
