#pragma once
/// @file ProgressBar.h
/// Progress display for long-running command-line tools.

#include <cstdio>
#include <string>
#include <string_view>

namespace tessera::heightgen {

/// Shows progress on a stream (normally stderr).
///
/// On a terminal it redraws one line in place:
/// `[#########...........] 42% hydraulic erosion`. On anything else (a CI
/// log, a pipe) redrawing would spam, so it prints a line when a stage starts
/// and at every 25% of overall progress.
class ProgressBar {
public:
    /// Decides between the two styles by asking whether `stream` is a TTY.
    explicit ProgressBar(std::FILE* stream);

    /// Reports the current stage and overall progress in [0, 1].
    void update(std::string_view stage, float fraction);
    /// Ends the redrawn line so later output starts on a fresh one.
    void finish();

private:
    void draw(std::string_view stage, int percent);

    std::FILE* mStream;
    bool mTerminal = false;
    int mLastPercent = -1;
    int mNextQuarter = 25;
    std::string mStage;
    size_t mDrawnWidth = 0;
};

} // namespace tessera::heightgen
