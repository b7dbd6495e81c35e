#include "CreatureProgress.h"

#include <algorithm>
#include <unistd.h>

namespace tessera::creature {

CreatureProgress::CreatureProgress(std::FILE* stream) : mStream(stream), mTerminal(isatty(fileno(stream)) != 0) {}

void CreatureProgress::update(const char* stage, float overall) {
    int percent = static_cast<int>(std::clamp(overall, 0.0f, 1.0f) * 100.0f);
    bool newStage = mStage != stage;
    if (!newStage && percent == mLastPercent) return;
    mLastPercent = percent;
    mStage = stage;
    if (!mTerminal) {
        if (newStage) std::fprintf(mStream, "tessera-creaturegen: %3d%% %s\n", percent, stage);
        return;
    }
    constexpr int kWidth = 30;
    int filled = percent * kWidth / 100;
    std::fprintf(mStream, "\r[%s%s] %3d%% %-10s", std::string(static_cast<size_t>(filled), '#').c_str(),
                 std::string(static_cast<size_t>(kWidth - filled), '.').c_str(), percent, stage);
    std::fflush(mStream);
}

void CreatureProgress::finish() {
    if (mTerminal && mLastPercent >= 0) std::fputc('\n', mStream);
    mLastPercent = -1;
}

} // namespace tessera::creature
