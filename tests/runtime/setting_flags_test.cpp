// The runtime speaks its own language and the demo names its flags where it
// reports: every word the runtime uses for a setting has the demo's flag in
// game_sample/SettingFlags.cpp, a message about a setting comes out with the
// flag in its place, and advice names settings the host's way.
#include "tessera/demo/SettingFlags.h"
#include "tessera/runtime/Options.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace tessera::runtime {
namespace {

TEST(SettingFlags, EveryRuntimeSettingHasADemoFlag) {
    std::set<std::string> words;
    for (const char* word : setting::all()) {
        EXPECT_TRUE(words.insert(word).second) << "\"" << word << "\" is listed twice";
        const std::string flag = demo::flagFor(word);
        EXPECT_NE(flag, word) << "the demo has no flag for the runtime's \"" << word << "\"";
        EXPECT_NE(flag.find("--"), std::string::npos) << word << " -> " << flag;
    }
}

TEST(SettingFlags, TheTableIsSortedAndEachSettingNamedOnce) {
    const auto table = demo::settingFlags();
    for (size_t i = 1; i < table.size(); ++i)
        EXPECT_LT(table[i - 1].words, table[i].words) << "at \"" << table[i].words << "\"";
}

TEST(SettingFlags, AMessageAboutASettingNamesTheFlag) {
    const Error error = failSetting(setting::kTerrainMode, " lowres: backend r2vb does not draw it");
    EXPECT_EQ(error.message, "terrain mode lowres: backend r2vb does not draw it");
    EXPECT_EQ(demo::withFlags(error), "--terrain-mode lowres: backend r2vb does not draw it");
    // A message about no setting, or a setting the demo does not know, stays as it is.
    EXPECT_EQ(demo::withFlags(fail("out of device memory")), "out of device memory");
    EXPECT_EQ(demo::withFlags(failSetting("frobnication", " 3: too much")), "frobnication 3: too much");
}

TEST(SettingFlags, TheDefaultReporterKeepsTheRuntimesWords) {
    const Options options; // no reporter: the runtime's own
    const Reporter& reporter = reporterFor(options);
    EXPECT_EQ(reporter.name(setting::kDeviceMemoryCap), "device memory cap");
    EXPECT_EQ(reporter.wording(failSetting(setting::kAgents, " 0: too few")), "agents 0: too few");

    struct Flags final : Reporter {
        std::string name(std::string_view words) const override { return demo::flagFor(words); }
    } flags;
    Options named;
    named.reporter = &flags;
    EXPECT_EQ(reporterFor(named).name(setting::kListBackends), "run --list-backends");
    EXPECT_EQ(reporterFor(named).wording(failSetting(setting::kAgents, " 0: too few")), "--agents 0: too few");
}

} // namespace
} // namespace tessera::runtime
