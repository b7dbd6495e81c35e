#include "BenchOutputs.h"

#include "tessera/core/Log.h"
#include "tessera/profiler/TraceWriter.h"

#include <cstdio>
#include <fstream>
#include <set>

namespace tessera::runtime {

Status writeBenchOutputs(const Options& options, const std::string& json, const std::string& table) {
    if (options.benchOut.empty()) {
        std::fputs(json.c_str(), stdout);
        std::fputs(table.c_str(), stderr);
        return {};
    }
    std::ofstream out(options.benchOut, std::ios::binary | std::ios::trunc);
    if (!(out << json) || !out.flush()) return fail("--out ", options.benchOut, ": cannot write the file");
    std::fputs(table.c_str(), stdout);
    std::fflush(stdout); // before the log line on stderr
    log::info("wrote " + options.benchOut);
    return {};
}

std::filesystem::path benchTraceDirectory(const Options& options) {
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

} // namespace tessera::runtime
