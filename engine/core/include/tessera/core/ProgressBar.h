#pragma once
/// @file ProgressBar.h
/// The one progress display of the command-line tools (tessera-heightgen,
/// tessera-creaturegen): a stage name and the overall fraction done.

#include <cstdio>
#include <string>
#include <string_view>

namespace tessera::core {

/// Shows progress on a stream (normally stderr).
///
/// On a terminal it redraws one line in place:
/// `[#########.....................]  30% hydraulic erosion`. On anything else
/// (a CI log, a pipe) redrawing would spam, so it prints a plain line,
/// `tessera-heightgen:  30% hydraulic erosion`, when a stage starts and,
/// if asked, each time the overall progress passes another step. A quiet bar
/// shows nothing, so a tool's `--quiet` needs no test at every call.
class ProgressBar {
public:
    /// `tool` starts every plain line. `plainStepPercent` > 0 adds a plain
    /// line at every multiple of it (25: at 25%, 50%, 75% and 100%); 0 prints
    /// plain lines only when a stage starts. The style is chosen by asking
    /// whether `stream` is a terminal.
    ProgressBar(std::FILE* stream, std::string tool, bool quiet = false, int plainStepPercent = 0);

    /// Reports the current stage and the overall progress in [0, 1] (clamped).
    /// Draws only on a visible change: callers may report as often as they like.
    void update(std::string_view stage, float fraction);
    /// Ends the redrawn line so later output starts on a fresh one. Safe to
    /// call twice (an error path and the normal end).
    void finish();

private:
    void draw(int percent);
    void printPlain(int percent);

    std::FILE* mStream;
    std::string mTool;
    bool mQuiet = false;
    bool mTerminal = false;
    int mStep = 0;
    int mNextStep = 0;
    int mLastPercent = -1;
    std::string mStage;
    size_t mDrawnWidth = 0;
};

} // namespace tessera::core
