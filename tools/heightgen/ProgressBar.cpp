#include "ProgressBar.h"

#include <algorithm>

#include <unistd.h>

namespace tessera::heightgen {
namespace {
constexpr int kBarWidth = 30;
} // namespace

ProgressBar::ProgressBar(std::FILE* stream)
    : mStream(stream), mTerminal(isatty(fileno(stream)) != 0) {}

void ProgressBar::update(std::string_view stage, float fraction) {
    const int percent = std::clamp(int(fraction * 100.0f), 0, 100);
    const bool newStage = stage != mStage;
    if (newStage) mStage = std::string(stage);

    if (mTerminal) {
        // Redraw only on visible change: the generator reports far more often.
        if (newStage || percent != mLastPercent) draw(stage, percent);
    } else {
        if (newStage) std::fprintf(mStream, "tessera-heightgen: %3d%% %s\n", percent, mStage.c_str());
        while (percent >= mNextQuarter && mNextQuarter <= 100) {
            std::fprintf(mStream, "tessera-heightgen: %3d%% %s\n", mNextQuarter, mStage.c_str());
            mNextQuarter += 25;
        }
        std::fflush(mStream);
    }
    mLastPercent = percent;
}

void ProgressBar::draw(std::string_view stage, int percent) {
    const int filled = percent * kBarWidth / 100;
    std::string line = "\r[";
    line.append(size_t(filled), '#');
    line.append(size_t(kBarWidth - filled), '.');
    line += "] ";
    line += std::to_string(percent);
    line += "% ";
    line += stage;
    // Pad over a longer stage name from the previous draw.
    const size_t width = line.size();
    if (width < mDrawnWidth) line.append(mDrawnWidth - width, ' ');
    mDrawnWidth = width;
    std::fputs(line.c_str(), mStream);
    std::fflush(mStream);
}

void ProgressBar::finish() {
    if (mTerminal && mDrawnWidth > 0) std::fputc('\n', mStream);
    std::fflush(mStream);
}

} // namespace tessera::heightgen
