// A backend whose initialize fails after making GPU objects
// (tests/plugins/InitFailsPlugin.cpp; docs/RELIABILITY.md, "Faults"): at
// start the run fails with the backend and the reason; in a switch the old
// backend draws on. Either way the host shuts the failed backend down, so the
// validation layer's object tracking finds nothing left when the device goes.
#include "tessera/profiler/Profiler.h"
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/SceneRun.h"
#include "SceneOptions.h"

#include <gtest/gtest.h>

#include <string>

namespace tessera::runtime {
namespace {

Options terrainOptions(const std::string& backend) {
    Options options = test::smallSceneOptions(backend, "terrain");
    options.pluginDirs.push_back(TESSERA_TEST_PLUGIN_DIR "/demo");
    return options;
}

TEST(BackendInitFailure, AtStartNamesTheBackendAndReleasesItsObjects) {
    profiler::Profiler::global().setEnabled(false);
    const uint64_t before = validationMessages();
    {
        auto run = SceneRun::create(terrainOptions("init-fails"), 2);
        ASSERT_FALSE(run);
        EXPECT_EQ(run.error().message.rfind("backend init-fails: the pipeline \"init-fails.draw\" does not build", 0),
                  0u)
            << run.error().message;
    }
    EXPECT_EQ(validationMessages(), before) << "objects of the failed initialize were left behind";
}

TEST(BackendInitFailure, InASwitchTheOldBackendDrawsOn) {
    profiler::Profiler::global().setEnabled(false);
    const uint64_t before = validationMessages();
    {
        auto created = SceneRun::create(terrainOptions("hulldomain"), 4);
        ASSERT_TRUE(created) << created.error().message;
        SceneRun& run = *created.value();
        ASSERT_TRUE(run.step(0, false));
        const Status switched = run.switchBackend("init-fails");
        ASSERT_FALSE(switched);
        EXPECT_NE(switched.error().message.find("init-fails"), std::string::npos) << switched.error().message;
        EXPECT_EQ(run.session().capabilities().name, "hulldomain");
        ASSERT_TRUE(run.step(1, true));
        EXPECT_FALSE(run.session().finish().empty()) << "the restored backend drew nothing";
    }
    EXPECT_EQ(validationMessages(), before);
}

} // namespace
} // namespace tessera::runtime
