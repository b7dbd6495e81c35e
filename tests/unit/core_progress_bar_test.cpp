// The tools' one progress display, on a stream that is not a terminal (a
// temporary file, as a CI log would be): plain lines per stage and per step,
// and nothing at all when quiet.

#include "tessera/core/ProgressBar.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using tessera::core::ProgressBar;

namespace {

// Runs `report` against a bar on a temporary file and returns what it printed.
template <class Report>
std::string printed(bool quiet, int step, Report report) {
    std::FILE* file = std::tmpfile();
    EXPECT_NE(file, nullptr);
    {
        ProgressBar bar(file, "tool", quiet, step);
        report(bar);
        bar.finish();
    }
    std::rewind(file);
    std::string text;
    for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += char(c);
    std::fclose(file);
    return text;
}

void twoStages(ProgressBar& bar) {
    for (int k = 0; k <= 10; ++k) bar.update("first", 0.05f * float(k));
    for (int k = 0; k <= 10; ++k) bar.update("second", 0.5f + 0.05f * float(k));
}

} // namespace

TEST(CoreProgressBar, PlainLinePerStage) {
    EXPECT_EQ(printed(false, 0, twoStages), "tool:   0% first\ntool:  50% second\n");
}

TEST(CoreProgressBar, PlainLinesAtEveryStep) {
    EXPECT_EQ(printed(false, 25, twoStages),
              "tool:   0% first\ntool:  25% first\ntool:  50% first\ntool:  50% second\n"
              "tool:  75% second\ntool: 100% second\n");
}

TEST(CoreProgressBar, ClampsAndQuietPrintsNothing) {
    EXPECT_EQ(printed(false, 0, [](ProgressBar& bar) { bar.update("over", 7.0f); }), "tool: 100% over\n");
    EXPECT_EQ(printed(true, 25, twoStages), "");
}
