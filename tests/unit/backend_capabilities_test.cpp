// Each GPU backend checks a device against what its technique needs and
// names every missing feature in plain words, so `--list-backends` and a
// failed start say why (e.g. streamout on a device without transform
// feedback). No device is needed: the features are described, not queried.
#include "tessera/backend/PluginLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace tessera;
using namespace tessera::backend;
using tessera::device::DeviceFeatures;

namespace {

BackendCapabilities capabilitiesOn(const std::string& name, const DeviceFeatures& features) {
    PluginLoader loader;
    loader.addSearchDirectory(TESSERA_PLUGIN_DIR);
    BackendRegistry registry;
    EXPECT_TRUE(loader.loadBackend(name, registry).ok()) << name;
    auto backend = registry.create(name);
    EXPECT_TRUE(backend.ok()) << name;
    return backend.ok() ? backend.value()->capabilities(&features) : BackendCapabilities{};
}

DeviceFeatures everything() {
    DeviceFeatures f;
    f.deviceName = "test device";
    f.tessellationShader = f.geometryShader = f.transformFeedback = f.pipelineStatistics = true;
    f.timestamps = f.fillModeNonSolid = f.vertexStores = f.multiDrawIndirect = true;
    f.meshShader = f.meshShaderQueries = true;
    f.maxTessellationLevel = 64;
    return f;
}

bool mentions(const BackendCapabilities& caps, const std::string& words) {
    return std::any_of(caps.missing.begin(), caps.missing.end(),
                       [&](const std::string& m) { return m.find(words) != std::string::npos; });
}

} // namespace

TEST(BackendCapabilities, EveryGpuBackendRunsOnAFullDevice) {
    for (const char* name : {"r2vb", "streamout", "hulldomain", "meshshader"}) {
        const BackendCapabilities caps = capabilitiesOn(name, everything());
        EXPECT_TRUE(caps.supported()) << name;
        EXPECT_EQ(caps.terrainModes, 0b111u) << name << " draws every terrain mode";
    }
}

TEST(BackendCapabilities, StreamoutNamesMissingTransformFeedbackAndGeometryShaders) {
    DeviceFeatures f = everything();
    f.transformFeedback = false;
    f.geometryShader = false;
    const BackendCapabilities caps = capabilitiesOn("streamout", f);
    EXPECT_FALSE(caps.supported());
    EXPECT_TRUE(mentions(caps, "transform feedback"));
    EXPECT_TRUE(mentions(caps, "geometry shaders"));
    // r2vb uses neither, by design.
    EXPECT_TRUE(capabilitiesOn("r2vb", f).supported());
}

TEST(BackendCapabilities, EmulatedBackendsNeedMultiDrawIndirect) {
    DeviceFeatures f = everything();
    f.multiDrawIndirect = false;
    for (const char* name : {"r2vb", "streamout"}) EXPECT_TRUE(mentions(capabilitiesOn(name, f), "multiDrawIndirect")) << name;
    EXPECT_TRUE(capabilitiesOn("hulldomain", f).supported());
}

TEST(BackendCapabilities, MeshshaderNamesMissingMeshShadersAndNeedsNoTessellator) {
    DeviceFeatures f = everything();
    f.meshShader = false;
    EXPECT_TRUE(mentions(capabilitiesOn("meshshader", f), "task and mesh shaders (VK_EXT_mesh_shader)"));
    EXPECT_TRUE(capabilitiesOn("hulldomain", f).supported());
    f = everything();
    f.tessellationShader = false;
    f.geometryShader = false;
    f.transformFeedback = false;
    EXPECT_TRUE(capabilitiesOn("meshshader", f).supported());
    EXPECT_EQ(capabilitiesOn("meshshader", f).maxTessFactor, 64.0f);
}

TEST(BackendCapabilities, HulldomainNamesMissingTessellation) {
    DeviceFeatures f = everything();
    f.tessellationShader = false;
    EXPECT_TRUE(mentions(capabilitiesOn("hulldomain", f), "tessellation shaders"));
    EXPECT_TRUE(capabilitiesOn("r2vb", f).supported());
    EXPECT_TRUE(capabilitiesOn("streamout", f).supported());
    f = everything();
    f.maxTessellationLevel = 16;
    EXPECT_TRUE(mentions(capabilitiesOn("hulldomain", f), "tessellation level 64"));
}
