// Timings the report must not chart as facts (docs/BACKENDS.md, "The
// comparison report"): a main pass that is a vanishing share of the
// wall-clock frame on a CPU device, and a GPU frame longer than the frame.

#include "report/BenchInput.h"
#include "report/Plausibility.h"

#include <gtest/gtest.h>

using namespace tessera::report;

namespace {

BenchRecord record(const std::string& device, double mainMs, double otherMs, double cpuMs) {
    BenchRecord r;
    r.backend = "r2vb";
    r.device = device;
    r.view = "far";
    r.mode = "adaptive";
    r.metric = "detail";
    r.passes = {{"r2vb.cage", otherMs}, {"terrain.adaptive", mainMs}};
    r.gpuMs = mainMs + otherMs;
    r.cpuFrameMs = cpuMs;
    return r;
}

constexpr const char* kLavapipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
constexpr const char* kH100 = "NVIDIA H100 80GB HBM3";

} // namespace

TEST(ReportFlags, KnowsCpuDevices) {
    EXPECT_TRUE(isCpuDevice(kLavapipe));
    EXPECT_TRUE(isCpuDevice("SwiftShader Device (Subzero)"));
    EXPECT_FALSE(isCpuDevice(kH100));
}

TEST(ReportFlags, TheIssuesR2vbPassIsFlagged) {
    // r2vb's main terrain pass read 0.13 ms inside a 30 ms frame on lavapipe.
    const auto flags = assessRecord(record(kLavapipe, 0.13, 0.05, 30.0));
    ASSERT_EQ(flags.size(), 1u);
    EXPECT_EQ(flags[0].pass, "terrain.adaptive");
    EXPECT_TRUE(isFlagged(flags, "terrain.adaptive"));
    EXPECT_FALSE(isFlagged(flags, "r2vb.cage")); // small factor passes are plausible
    EXPECT_NE(flags[0].reason.find("0.130 ms, 0.43% of the 30.00 ms wall-clock frame"), std::string::npos)
        << flags[0].reason;
}

TEST(ReportFlags, PlausibleMainPassesAreNot) {
    EXPECT_TRUE(assessRecord(record(kLavapipe, 18.0, 0.1, 30.0)).empty());
    // Exactly at the threshold is plausible; just under is not (other
    // passes make up the frame here).
    EXPECT_TRUE(assessRecord(record(kLavapipe, 0.6, 20.0, 30.0)).empty());
    EXPECT_EQ(assessRecord(record(kLavapipe, 0.59, 20.0, 30.0)).size(), 1u);
    // A real GPU finishes a pass far inside the CPU's frame: not flagged.
    EXPECT_TRUE(assessRecord(record(kH100, 0.29, 0.02, 30.0)).empty());
}

TEST(ReportFlags, AFrameTheGpuPassesDoNotAccountForIsFlaggedOnItsMainPass) {
    // lavapipe, 320x180, far adaptive/screen (measured): r2vb's passes sum to
    // 2.89 ms of an 8.59 ms frame, its main pass 0.42 ms; hulldomain's 4.85
    // of 6.75 ms.
    const auto r2vb = assessRecord(record(kLavapipe, 0.418, 2.47, 8.59));
    ASSERT_EQ(r2vb.size(), 1u);
    EXPECT_EQ(r2vb[0].pass, "terrain.adaptive");
    EXPECT_NE(r2vb[0].reason.find("only 33.6% of the 8.59 ms wall-clock frame"), std::string::npos) << r2vb[0].reason;
    EXPECT_TRUE(assessRecord(record(kLavapipe, 4.80, 0.05, 6.75)).empty());
    // On a real GPU the CPU's frame may be much longer than the GPU's.
    EXPECT_TRUE(assessRecord(record(kH100, 0.418, 2.47, 8.59)).empty());
}

TEST(ReportFlags, TheThresholdIsARule) {
    PlausibilityRules strict;
    strict.minMainPassShare = 0.7;
    EXPECT_EQ(assessRecord(record(kLavapipe, 18.0, 0.1, 30.0), strict).size(), 1u);
}

TEST(ReportFlags, AGpuFrameLongerThanTheFrameIsFlaggedOnAnyDevice) {
    const auto flags = assessRecord(record(kH100, 3.0, 0.5, 2.0));
    ASSERT_EQ(flags.size(), 1u);
    EXPECT_EQ(flags[0].pass, "");
    EXPECT_TRUE(isFlagged(flags, ""));
    EXPECT_TRUE(assessRecord(record(kH100, 1.0, 0.1, 1.0)).empty()); // within 1.25x + 0.05 ms
}

TEST(ReportFlags, NoWallClockFrameNoFlags) {
    EXPECT_TRUE(assessRecord(record(kLavapipe, 0.13, 0.0, 0.0)).empty());
}
