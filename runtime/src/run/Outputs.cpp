#include "tessera/runtime/Outputs.h"

#include "tessera/runtime/Settings.h"
#include "tessera/core/ImageFile.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/profiler/TraceWriter.h"
#include "tessera/terrain/HeightMapIO.h"

#include <cstdio>

namespace tessera::runtime {

namespace {

Status writeHeights(const Options& options, RenderSession& session, const terrain::Terrain& terrain) {
    const terrain::HeightField& field = terrain.field();
    auto gpu = session.readHeights();
    if (!gpu) return failSetting(setting::kHeightDump, ": ", gpu.error().message);
    const std::string gpuPath = options.dumpHeights + ".gpu.png";
    const std::string cpuPath = options.dumpHeights + ".cpu.png";
    if (auto w = terrain::saveHeightMapPng16(gpuPath, field.width(), field.height(), gpu.value()); !w) return w;
    if (auto w = terrain::saveHeightMapPng16(cpuPath, field.width(), field.height(), field.samples()); !w) return w;
    log::info("wrote " + gpuPath + " and " + cpuPath);
    return {};
}

} // namespace

Status writeOutputs(const Options& options, RenderSession& session, const terrain::Terrain& terrain,
                    const std::vector<uint8_t>& pixels, uint32_t frames) {
    auto& profiler = profiler::Profiler::global();
    const uint32_t width = session.width(), height = session.height();
    if (!options.screenshot.empty()) {
        if (pixels.empty())
            return failSetting(setting::kScreenshot, " ", options.screenshot, ": the ", session.capabilities().name,
                        " backend renders no pixels");
        if (auto w = writePng(options.screenshot, {width, height, pixels}); !w) return w;
        log::info("wrote " + options.screenshot);
    }
    if (!options.capture.empty()) {
        profiler::TraceMetadata meta;
        meta.backend = session.capabilities().name;
        meta.device = session.deviceName();
        meta.driver = session.driverName();
        meta.width = width;
        meta.height = height;
        if (auto w = profiler::writeChromeTrace(profiler, options.capture, meta); !w) return w;
        log::info("wrote " + options.capture);
    }
    if (!options.benchmark.empty()) {
        const uint32_t warmup = options.warmup.value_or(0);
        profiler.discardFramesBefore(warmup);
        auto summary = profiler::summarize(profiler);
        profiler::BenchmarkInfo info;
        info.backend = session.capabilities().name;
        info.device = session.deviceName();
        info.driver = session.driverName();
        info.scene = options.scene;
        info.width = width;
        info.height = height;
        info.warmupFrames = warmup;
        info.frames = frames > warmup ? frames - warmup : 0;
        if (auto w = profiler::writeBenchmarkJson(summary, info, profiler, options.benchmark); !w) return w;
        std::printf("%s", profiler::formatTable(summary).c_str());
        log::info("wrote " + options.benchmark);
    }
    if (!options.dumpHeights.empty())
        if (auto w = writeHeights(options, session, terrain); !w) return w;
    return {};
}

} // namespace tessera::runtime
