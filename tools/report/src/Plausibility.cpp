#include "report/Plausibility.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace tessera::report {
namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

std::string ms(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, value < 1.0 ? "%.3f ms" : "%.2f ms", value);
    return buffer;
}

std::string percent(double share) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, share < 0.1 ? "%.2f%%" : "%.1f%%", share * 100.0);
    return buffer;
}

} // namespace

bool isCpuDevice(const std::string& deviceName) {
    const std::string name = lower(deviceName);
    return name.find("llvmpipe") != std::string::npos || name.find("lavapipe") != std::string::npos ||
           name.find("swiftshader") != std::string::npos;
}

std::vector<TimingFlag> assessRecord(const BenchRecord& r, const PlausibilityRules& rules) {
    std::vector<TimingFlag> flags;
    if (r.cpuFrameMs <= 0.0) return flags; // nothing to check against
    if (r.gpuMs > r.cpuFrameMs * rules.maxGpuOverFrame + rules.slackMs)
        flags.push_back({"", "GPU frame " + ms(r.gpuMs) + " exceeds the wall-clock frame " + ms(r.cpuFrameMs) +
                                 ": steady frames cannot run longer on the GPU than between the CPU's frames"});
    if (isCpuDevice(r.device)) {
        for (const PassTime& pass : r.passes) {
            if (pass.name != r.mainPassName()) continue;
            const double share = pass.gpuMs / r.cpuFrameMs;
            const double frameShare = r.gpuMs / r.cpuFrameMs;
            if (share < rules.minMainPassShare)
                flags.push_back({pass.name, pass.name + " reads " + ms(pass.gpuMs) + ", " + percent(share) +
                                                " of the " + ms(r.cpuFrameMs) + " wall-clock frame, on a CPU device (" +
                                                r.device +
                                                ") where it draws every triangle: its timestamps miss the deferred "
                                                "rasterisation"});
            else if (frameShare < rules.minGpuFrameShare)
                flags.push_back({pass.name, pass.name + " reads " + ms(pass.gpuMs) + ", and all GPU passes " +
                                                ms(r.gpuMs) + ", only " + percent(frameShare) + " of the " +
                                                ms(r.cpuFrameMs) + " wall-clock frame on a CPU device (" + r.device +
                                                "): the rest is most likely this pass's deferred rasterisation, "
                                                "which its timestamps miss"});
        }
    }
    return flags;
}

bool isFlagged(const std::vector<TimingFlag>& flags, const std::string& name) {
    return std::any_of(flags.begin(), flags.end(), [&](const TimingFlag& f) { return f.pass == name; });
}

} // namespace tessera::report
