// --hide-features' parser (cli::parseFeatureMask) and mask (device::FeatureMask):
// names in, flags cleared, an unknown name refused with the known ones listed.
#include "tessera/cli/FeatureMaskText.h"
#include "tessera/device/FeatureMask.h"

#include <gtest/gtest.h>

using namespace tessera::device;
using tessera::cli::parseFeatureMask;

namespace {

DeviceFeatures everything() {
    DeviceFeatures f;
    f.tessellationShader = f.geometryShader = f.transformFeedback = f.pipelineStatistics = true;
    f.timestamps = f.fillModeNonSolid = f.vertexStores = f.multiDrawIndirect = true;
    f.maxTessellationLevel = 64;
    f.meshShader = f.meshShaderQueries = true;
    f.maxMeshOutputVertices = f.maxMeshOutputPrimitives = f.maxMeshWorkGroupInvocations = 256;
    f.maxTaskPayloadSize = 16384;
    return f;
}

} // namespace

TEST(FeatureMask, HidesExactlyTheNamedFeatures) {
    auto mask = parseFeatureMask("tessellation,multi-draw-indirect");
    ASSERT_TRUE(mask) << mask.error().message;
    DeviceFeatures f = everything();
    applyFeatureMask(mask.value(), f);
    EXPECT_FALSE(f.tessellationShader);
    EXPECT_EQ(f.maxTessellationLevel, 0u) << "no tessellation, no level";
    EXPECT_FALSE(f.multiDrawIndirect);
    EXPECT_TRUE(f.geometryShader && f.transformFeedback && f.pipelineStatistics && f.timestamps &&
                f.fillModeNonSolid && f.vertexStores);
}

TEST(FeatureMask, EveryListedNameParsesAndAnEmptyListHidesNothing) {
    auto all = parseFeatureMask("tessellation,geometry,transform-feedback,pipeline-statistics,timestamps,wireframe,"
                                "vertex-stores,multi-draw-indirect,mesh-shader");
    ASSERT_TRUE(all) << all.error().message;
    DeviceFeatures f = everything();
    applyFeatureMask(all.value(), f);
    EXPECT_FALSE(f.tessellationShader || f.geometryShader || f.transformFeedback || f.pipelineStatistics ||
                 f.timestamps || f.fillModeNonSolid || f.vertexStores || f.multiDrawIndirect || f.meshShader);
    auto none = parseFeatureMask("");
    ASSERT_TRUE(none);
    EXPECT_TRUE(none.value().empty());
}

TEST(FeatureMask, HidingMeshShadersHidesTheirQueriesAndLimits) {
    auto mask = parseFeatureMask("mesh-shader");
    ASSERT_TRUE(mask) << mask.error().message;
    DeviceFeatures f = everything();
    applyFeatureMask(mask.value(), f);
    EXPECT_FALSE(f.meshShader || f.meshShaderQueries);
    EXPECT_EQ(f.maxMeshOutputVertices + f.maxMeshOutputPrimitives + f.maxMeshWorkGroupInvocations +
                  f.maxTaskPayloadSize,
              0u);
    EXPECT_TRUE(f.tessellationShader && f.pipelineStatistics) << "nothing else hidden";
    EXPECT_EQ(f.maxTessellationLevel, 64u);
}

TEST(FeatureMask, HidingPipelineStatisticsHidesTheMeshShaderQueries) {
    auto mask = parseFeatureMask("pipeline-statistics");
    ASSERT_TRUE(mask) << mask.error().message;
    DeviceFeatures f = everything();
    applyFeatureMask(mask.value(), f);
    EXPECT_FALSE(f.pipelineStatistics || f.meshShaderQueries);
    EXPECT_TRUE(f.meshShader);
}

TEST(FeatureMask, AnUnknownNameIsRefusedWithTheKnownOnes) {
    for (const char* list : {"tessellation,warp", "Tessellation", "tessellation,", ",geometry"}) {
        auto mask = parseFeatureMask(list);
        ASSERT_FALSE(mask) << list;
        EXPECT_NE(mask.error().message.find("unknown feature"), std::string::npos) << mask.error().message;
        EXPECT_NE(mask.error().message.find(featureMaskNames()), std::string::npos) << mask.error().message;
    }
}
