#pragma once
/// @file ReportOptions.h
/// Command-line options of tessera-report.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace tessera::reporttool {

struct ReportOptions {
    std::filesystem::path dir; ///< --dir: the inputs (and --run's outputs)
    std::filesystem::path out; ///< --out: the HTML (default DIR/report.html)
    bool run = false;          ///< --run: run tessera-demo first
    uint32_t width = 1280;     ///< --width, --height: --run's size
    uint32_t height = 720;
    uint32_t frames = 10; ///< --frames, --warmup: --run's measured and warm-up frames per row
    uint32_t warmup = 3;
    std::string camera = "1800,900,6800,-30,-16"; ///< --camera: the screenshots' view
    std::string device;                           ///< --device: passed to tessera-demo
    std::filesystem::path demo;                   ///< --demo: tessera-demo (default: next to tessera-report)
    double minMainPassPercent = 2.0;              ///< --min-main-share
    double minGpuFramePercent = 50.0;             ///< --min-gpu-share
    bool help = false;
};

/// Parses argv[1..argc) with the shared parser; one-line errors.
Result<ReportOptions> parseReportOptions(int argc, const char* const* argv);

std::string reportUsage();

} // namespace tessera::reporttool
