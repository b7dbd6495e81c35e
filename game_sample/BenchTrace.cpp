#include "BenchTrace.h"

#include "tessera/core/Log.h"
#include "tessera/profiler/TraceWriter.h"

#include <set>

namespace tessera::demo {

std::filesystem::path benchTraceDirectory(const DemoOptions& options) {
    if (!options.benchOutDir.empty()) return options.benchOutDir;
    if (options.backend != "all") return {};
    const auto parent = std::filesystem::path(options.benchOut).parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

const char* internBenchName(const std::string& name) {
    static auto* names = new std::set<std::string>();
    return names->insert(name).first->c_str();
}

Status writeBenchTrace(const profiler::Profiler& profiler, const std::string& path, const std::string& application,
                       const RenderSession& session) {
    profiler::TraceMetadata meta;
    meta.application = application;
    meta.backend = session.capabilities().name;
    meta.device = session.deviceName();
    meta.driver = session.driverName();
    meta.width = session.width();
    meta.height = session.height();
    if (auto written = profiler::writeChromeTrace(profiler, path, meta); !written) return written;
    log::info("wrote " + path);
    return {};
}

} // namespace tessera::demo
