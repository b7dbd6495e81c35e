#include "tessera/core/ProgressBar.h"

#include <algorithm>

#include <unistd.h>

namespace tessera::core {
namespace {
constexpr int kBarWidth = 30;
} // namespace

ProgressBar::ProgressBar(std::FILE* stream, std::string tool, bool quiet, int plainStepPercent)
    : mStream(stream), mTool(std::move(tool)), mQuiet(quiet), mTerminal(isatty(fileno(stream)) != 0),
      mStep(std::max(plainStepPercent, 0)), mNextStep(mStep) {}

void ProgressBar::update(std::string_view stage, float fraction) {
    if (mQuiet) return;
    const int percent = int(std::clamp(fraction, 0.0f, 1.0f) * 100.0f);
    const bool newStage = stage != mStage;
    // Tools report far more often than the display can change.
    if (!newStage && percent == mLastPercent) return;
    if (newStage) mStage = std::string(stage);
    mLastPercent = percent;

    if (mTerminal) {
        draw(percent);
        return;
    }
    if (newStage) printPlain(percent);
    // Steps are counted over the whole run, not per stage, so a log gets the
    // same few lines however the work is split into stages.
    while (mStep > 0 && percent >= mNextStep && mNextStep <= 100) {
        printPlain(mNextStep);
        mNextStep += mStep;
    }
    std::fflush(mStream);
}

void ProgressBar::printPlain(int percent) {
    std::fprintf(mStream, "%s: %3d%% %s\n", mTool.c_str(), percent, mStage.c_str());
}

void ProgressBar::draw(int percent) {
    const int filled = percent * kBarWidth / 100;
    char number[8];
    std::snprintf(number, sizeof(number), "%3d%% ", percent);
    std::string line = "\r[";
    line.append(size_t(filled), '#');
    line.append(size_t(kBarWidth - filled), '.');
    line += "] ";
    line += number;
    line += mStage;
    // Pad over a longer stage name from the previous draw.
    const size_t width = line.size();
    if (width < mDrawnWidth) line.append(mDrawnWidth - width, ' ');
    mDrawnWidth = std::max(width, mDrawnWidth);
    std::fputs(line.c_str(), mStream);
    std::fflush(mStream);
}

void ProgressBar::finish() {
    if (mTerminal && mDrawnWidth > 0) std::fputc('\n', mStream);
    mDrawnWidth = 0;
    std::fflush(mStream);
}

} // namespace tessera::core
