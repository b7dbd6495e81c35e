#pragma once
/// @file CreatureProgress.h
/// The progress bar of tessera-creaturegen.

#include <cstdio>
#include <string>

namespace tessera::creature {

/// Shows the current stage and overall progress on a stream (stderr).
/// On a terminal it redraws one line (`[####......]  42% sculpt`); on a
/// pipe or log it prints one line per stage instead of spamming redraws.
class CreatureProgress {
public:
    explicit CreatureProgress(std::FILE* stream);

    /// Reports `stage` and overall progress in [0, 1].
    void update(const char* stage, float overall);
    /// Ends the redrawn line so later output starts on a fresh one.
    void finish();

private:
    std::FILE* mStream;
    bool mTerminal = false;
    int mLastPercent = -1;
    std::string mStage;
};

} // namespace tessera::creature
