#include "bench/BenchDriver.h"

#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/Instance.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/profiler/TraceWriter.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>

namespace tessera::runtime {
namespace {

std::vector<std::string> backendsFor(const Options& options, const BenchPlan& plan) {
    if (options.backend == "all") return plan.comparison;
    if (!options.backend.empty()) return {options.backend};
    if (!plan.everyPreferred) return {""}; // the session picks the device's best
    return {std::begin(kBackendPreference), std::end(kBackendPreference)};
}

Result<std::vector<std::string>> devicesFor(const Options& options, const BenchPlan& plan) {
    if (!options.device.empty() || !plan.everyDevice) return std::vector<std::string>{options.device};
    gpu::InstanceOptions io;
    io.validation = options.validation;
    auto instance = gpu::Instance::create(io);
    if (!instance) return instance.error();
    std::vector<std::string> devices;
    for (const auto& d : instance.value()->devices()) devices.push_back(std::to_string(d.index));
    return devices;
}

/// Where the per-backend traces go ("" for none): Options::benchOutDir,
/// else with --backend all next to the output or in the current directory.
std::filesystem::path traceDirectoryFor(const Options& options) {
    if (!options.benchOutDir.empty()) return options.benchOutDir;
    if (options.backend != "all") return {};
    const auto parent = std::filesystem::path(options.benchOut).parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

/// A CPU-track slice name that lives as long as the process (CpuEvent keeps
/// only the pointer, and the global profiler is never destroyed).
const char* internName(const std::string& name) {
    static auto* names = new std::set<std::string>();
    return names->insert(name).first->c_str();
}

} // namespace

BenchDriver::BenchDriver(const Options& options, BenchPlan plan) : mOptions(options), mPlan(std::move(plan)) {
    const uint32_t warmup = mOptions.warmup.value_or(0);
    mWarmup = mOptions.warmup && !(mPlan.alwaysWarmUp && warmup == 0) ? warmup : mPlan.warmup;
    mFrames = mOptions.frames ? mOptions.frames : mPlan.frames;
    const bool sized = mOptions.width || mOptions.height;
    mWidth = sized ? mOptions.width.value_or(kDefaultWidth) : mPlan.width;
    mHeight = sized ? mOptions.height.value_or(kDefaultHeight) : mPlan.height;
    if (!mPlan.renders) return;
    mBackends = backendsFor(mOptions, mPlan);
    mTraceDir = traceDirectoryFor(mOptions);
}

Result<BenchDriver> BenchDriver::start(const Options& options, BenchPlan plan) {
    BenchDriver driver(options, std::move(plan));
    if (!driver.mPlan.renders) return driver;
    profiler::Profiler::global().setEnabled(true);
    auto devices = devicesFor(options, driver.mPlan);
    if (!devices) return devices.error();
    driver.mDevices = std::move(devices.value());
    if (!driver.mTraceDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(driver.mTraceDir, ec);
        if (ec) return failSetting(setting::kTraceDirectory, " ", driver.mTraceDir.string(), ": ", ec.message());
    }
    return driver;
}

Options BenchDriver::runOptions(const std::string& backend) const {
    Options run = mOptions;
    run.backend = backend;
    run.width = mWidth;
    run.height = mHeight;
    return run;
}

Options BenchDriver::runOptions(const std::string& backend, const std::string& device) const {
    Options run = runOptions(backend);
    run.device = device;
    return run;
}

uint32_t BenchDriver::renderFrames(uint32_t first, uint32_t count,
                                   const std::function<void(uint32_t frame)>& render) const {
    auto& profiler = profiler::Profiler::global();
    // Task and mesh invocations are counted on the first measured frame (the
    // last mFrames of the run) only: their query slows the mesh stage, so
    // the other frames' times stay clean and the median is not moved.
    const uint32_t firstMeasured = first + count - std::min(count, mFrames);
    for (uint32_t frame = first; frame < first + count; ++frame) {
        if (frame == firstMeasured) profiler.requestMeshInvocationCount();
        profiler.beginFrame(frame);
        render(frame);
        profiler.endFrame();
    }
    return first + count;
}

void BenchDriver::markRow(const std::string& label, uint64_t firstFrame, uint64_t startNs) const {
    auto& profiler = profiler::Profiler::global();
    profiler.recordCpu({internName(label), profiler::Profiler::currentThreadId(), firstFrame, startNs,
                        profiler.nowNs() - startNs, 0});
}

std::string BenchDriver::tracePath(const std::string& stem) const {
    return mTraceDir.empty() ? std::string() : (mTraceDir / ("bench-" + stem + ".json")).string();
}

Status BenchDriver::writeTrace(const std::string& path, const RenderSession& session) const {
    if (path.empty()) return {};
    profiler::TraceMetadata meta;
    meta.application = std::string("tessera bench ") + mPlan.name;
    meta.backend = session.capabilities().name;
    meta.device = session.deviceName();
    meta.driver = session.driverName();
    meta.width = session.width();
    meta.height = session.height();
    if (auto written = profiler::writeChromeTrace(profiler::Profiler::global(), path, meta); !written) return written;
    log::info("wrote " + path);
    return {};
}

Status BenchDriver::skip(const std::string& backend, const Error& why, std::vector<std::string>& notes,
                         const std::string& device) const {
    if (mBackends.size() * mDevices.size() < 2 && !comparing()) return why;
    const std::string where = mPlan.everyDevice ? " on device " + device : std::string();
    const std::string reason = reporterFor(mOptions).wording(why);
    log::warning("skipping " + backend + where + ": " + reason);
    notes.push_back(backend + " skipped" + where + ": " + reason);
    return {};
}

Status BenchDriver::finish(size_t rows, const std::string& json, const std::string& table) const {
    if (mPlan.renders) profiler::Profiler::global().clear();
    if (rows == 0)
        return failSetting(mPlan.setting, ": no backend could run", mPlan.everyDevice ? " on any device" : "");
    if (mOptions.benchOut.empty()) {
        std::fputs(json.c_str(), stdout);
        std::fputs(table.c_str(), stderr);
        return {};
    }
    std::ofstream out(mOptions.benchOut, std::ios::binary | std::ios::trunc);
    if (!(out << json) || !out.flush())
        return failSetting(setting::kBenchOutput, " ", mOptions.benchOut, ": cannot write the file");
    std::fputs(table.c_str(), stdout);
    std::fflush(stdout); // before the log line on stderr
    log::info("wrote " + mOptions.benchOut);
    return {};
}

} // namespace tessera::runtime
